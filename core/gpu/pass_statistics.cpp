#include "core/gpu/pass_statistics.h"

#include "core/gpu/context.h"
#include "core/gpu/vk_check.h"

namespace tp {
namespace {

// In the order the device writes them (bit order): PipelineCounts' fields.
constexpr VkQueryPipelineStatisticFlags kCounted =
    VK_QUERY_PIPELINE_STATISTIC_INPUT_ASSEMBLY_PRIMITIVES_BIT | VK_QUERY_PIPELINE_STATISTIC_CLIPPING_INVOCATIONS_BIT |
    VK_QUERY_PIPELINE_STATISTIC_CLIPPING_PRIMITIVES_BIT | VK_QUERY_PIPELINE_STATISTIC_FRAGMENT_SHADER_INVOCATIONS_BIT;
constexpr uint32_t kValues = 4;

} // namespace

PassStatistics::PassStatistics(GpuContext& ctx, uint32_t maxPasses) : ctx_(ctx), capacity_(maxPasses) {
    if (!ctx.caps.pipelineStatisticsQuery) return;
    VkQueryPoolCreateInfo ci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    ci.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
    ci.queryCount = maxPasses;
    ci.pipelineStatistics = kCounted;
    VK_CHECK(vkCreateQueryPool(ctx.device, &ci, nullptr, &pool_));
}

PassStatistics::~PassStatistics() {
    if (pool_) vkDestroyQueryPool(ctx_.device, pool_, nullptr);
}

void PassStatistics::beginFrame(VkCommandBuffer cmd) {
    names_.clear();
    if (pool_) vkCmdResetQueryPool(cmd, pool_, 0, capacity_);
}

uint32_t PassStatistics::begin(VkCommandBuffer cmd, const std::string& pass) {
    if (!pool_ || names_.size() >= capacity_) return ~0u; // beyond capacity: not counted
    names_.push_back(pass);
    const uint32_t query = uint32_t(names_.size() - 1);
    vkCmdBeginQuery(cmd, pool_, query, 0);
    return query;
}

void PassStatistics::end(VkCommandBuffer cmd, uint32_t query) {
    if (query != ~0u) vkCmdEndQuery(cmd, pool_, query);
}

std::vector<PassCounts> PassStatistics::read() const {
    if (!pool_ || names_.empty()) return {};
    std::vector<uint64_t> v(names_.size() * kValues);
    VK_CHECK(vkGetQueryPoolResults(ctx_.device, pool_, 0, uint32_t(names_.size()), v.size() * sizeof(uint64_t),
                                   v.data(), kValues * sizeof(uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    std::vector<PassCounts> out;
    for (size_t i = 0; i < names_.size(); ++i) {
        const uint64_t* q = &v[i * kValues];
        out.push_back({names_[i], {q[0], q[1], q[2], q[3]}});
    }
    return out;
}

} // namespace tp
