#include "core/gpu/profiler.h"

#include <algorithm>

#include "core/gpu/context.h"
#include "core/gpu/vk_check.h"

namespace tp {

GpuProfiler::GpuProfiler(GpuContext& ctx, uint32_t maxScopes)
    : ctx_(ctx), capacity_(maxScopes + 1) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = capacity_ * 3; // a begin and an end per scope, and lavapipe's closer
    VK_CHECK(vkCreateQueryPool(ctx.device, &info, nullptr, &pool_));
}

GpuProfiler::~GpuProfiler() {
    vkDestroyQueryPool(ctx_.device, pool_, nullptr);
}

void GpuProfiler::beginFrame(VkCommandBuffer cmd) {
    vkCmdResetQueryPool(cmd, pool_, 0, capacity_ * 3);
    used_ = 0;
    beginScope(cmd, "frame");
}

uint32_t GpuProfiler::beginScope(VkCommandBuffer cmd, const std::string& name) {
    if (used_ >= capacity_) throw GpuError("profiler: more timed scopes than planned");
    uint32_t scope = used_++;
    if (names_.size() <= scope) {
        names_.push_back(name);
        samples_.emplace_back();
    }
    names_[scope] = name;
    if (!ctx_.isCpuDevice()) {
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, pool_, scope * 2);
        return scope;
    }
    // lavapipe bins a timestamp into every tile of the scene being drawn and returns the time
    // the last tile reached it, and starts a new scene only for a stage other than TOP_OF_PIPE
    // (Mesa: lp_rast.c, lp_query.c, lvp_execute.c): a TOP_OF_PIPE begin was the start of the
    // pass's last tile, not of the pass. Here the begin gets a scene of its own, closed by a
    // second timestamp (never read): it is when the work before the pass finished.
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, scope * 2);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, capacity_ * 2 + scope);
    return scope;
}

void GpuProfiler::endScope(VkCommandBuffer cmd, uint32_t scope) {
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, pool_, scope * 2 + 1);
}

void GpuProfiler::endFrame(VkCommandBuffer cmd) {
    endScope(cmd, 0);
}

void GpuProfiler::collect() {
    std::vector<uint64_t> ticks(used_ * 2);
    VK_CHECK(vkGetQueryPoolResults(ctx_.device, pool_, 0, used_ * 2,
                                   ticks.size() * sizeof(uint64_t), ticks.data(), sizeof(uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    uint32_t bits = ctx_.caps.timestampValidBits;
    uint64_t mask = bits >= 64 ? ~0ull : ((1ull << bits) - 1);
    for (uint32_t i = 0; i < used_; ++i) {
        uint64_t begin = ticks[i * 2] & mask, end = ticks[i * 2 + 1] & mask;
        uint64_t delta = (end - begin) & mask; // wraps correctly within the valid bits
        samples_[i].push_back(double(delta) * ctx_.caps.timestampPeriodNs * 1e-6);
    }
}

void GpuProfiler::discardSamples() {
    for (auto& s : samples_)
        s.clear();
}

std::vector<TimingStats> GpuProfiler::stats() const {
    std::vector<TimingStats> out;
    for (size_t i = 0; i < names_.size(); ++i)
        out.push_back(summarize(names_[i], samples_[i]));
    return out;
}

TimingStats summarize(const std::string& name, std::vector<double> samples) {
    TimingStats t;
    t.name = name;
    t.frames = uint32_t(samples.size());
    if (samples.empty()) return t;
    std::sort(samples.begin(), samples.end());
    size_t n = samples.size();
    t.medianMs = n % 2 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
    t.minMs = samples.front();
    t.maxMs = samples.back();
    return t;
}

} // namespace tp
