#include "core/gpu/graph_plan.h"

#include <set>

namespace tp {
namespace {

constexpr VkPipelineStageFlags2 kShaderStages =
    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags2 kDepthStages =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;

VkImageUsageFlags imageUsage(Use use) {
    switch (use) {
    case Use::ColorAttachment:
    case Use::ColorResolve:
        return VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    case Use::DepthAttachment:
    case Use::DepthResolve:
    case Use::DepthTest:
        return VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    case Use::Sampled:
        return VK_IMAGE_USAGE_SAMPLED_BIT;
    case Use::StorageRead:
    case Use::StorageWrite:
        return VK_IMAGE_USAGE_STORAGE_BIT;
    case Use::TransferSrc:
        return VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    case Use::TransferDst:
        return VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    case Use::IndirectRead:
        return 0; // buffers only (imageOnly)
    }
    return 0;
}

VkBufferUsageFlags bufferUsage(Use use) {
    switch (use) {
    case Use::TransferSrc:
        return VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    case Use::TransferDst:
        return VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    case Use::IndirectRead:
        return VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
    default:
        return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    }
}

bool bindable(Use use) {
    return use == Use::Sampled || use == Use::DepthTest || use == Use::StorageRead ||
           use == Use::StorageWrite;
}

// Where a resource stands between uses. Every frame starts from "unknown contents, written
// by the previous frame": images from UNDEFINED (their contents are discarded), and the
// first use waits on all commands.
struct State {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 stages =
        VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT; // what a later write waits for
    VkAccessFlags2 access = VK_ACCESS_2_MEMORY_WRITE_BIT;
    bool lastWasWrite = true;
    // Since the last write (or layout change): the stages and accesses its barrier made the
    // contents visible to. A later reader outside them needs a barrier of its own, chained
    // after that one (its source stages), even though it reads in the same layout.
    VkPipelineStageFlags2 visibleStages = 0;
    VkAccessFlags2 visibleAccess = 0;
};

// Appends the barrier a use needs after the state `s`, if any, and moves `s` on.
void transition(uint32_t resource, bool isImage, Use use, State& s, std::vector<PlanBarrier>& out) {
    const UseInfo u = useInfo(use);
    const bool layoutChange = isImage && s.layout != u.layout;
    if (!layoutChange && !u.writes && !s.lastWasWrite) {
        // Read after read. Covered by the barrier after the last write: none. Otherwise (a
        // depth test after a sampled read of the same depth: other stages, other access) a
        // barrier chained after that one: its execution scope starts where the first ended,
        // and the writes, already available, become visible to this reader.
        if ((u.stages & ~s.visibleStages) || (u.access & ~s.visibleAccess)) {
            out.push_back({resource, isImage, isImage ? s.layout : VK_IMAGE_LAYOUT_UNDEFINED,
                           isImage ? s.layout : VK_IMAGE_LAYOUT_UNDEFINED, s.visibleStages,
                           u.stages, 0, u.access});
            s.visibleStages |= u.stages;
            s.visibleAccess |= u.access;
        }
        // A later write must wait for this reader too.
        s.stages |= u.stages;
        s.access |= u.access;
        return;
    }
    PlanBarrier b{resource,
                  isImage,
                  isImage ? s.layout : VK_IMAGE_LAYOUT_UNDEFINED,
                  isImage ? u.layout : VK_IMAGE_LAYOUT_UNDEFINED,
                  s.stages,
                  u.stages,
                  s.lastWasWrite ? s.access : VkAccessFlags2(0),
                  u.access};
    out.push_back(b);
    s = {u.layout, u.stages, u.access, u.writes, u.stages, u.access};
}

} // namespace

const char* useName(Use use) {
    switch (use) {
    case Use::ColorAttachment:
        return "colour attachment";
    case Use::ColorResolve:
        return "colour resolve";
    case Use::DepthAttachment:
        return "depth attachment";
    case Use::DepthResolve:
        return "depth resolve";
    case Use::DepthTest:
        return "depth test";
    case Use::Sampled:
        return "sampled";
    case Use::StorageRead:
        return "storage read";
    case Use::StorageWrite:
        return "storage write";
    case Use::TransferSrc:
        return "transfer source";
    case Use::TransferDst:
        return "transfer destination";
    case Use::IndirectRead:
        return "indirect read";
    }
    return "unknown use";
}

UseInfo useInfo(Use use) {
    switch (use) {
    case Use::ColorAttachment:
        return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, true, true};
    case Use::ColorResolve:
        return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                true, false};
    case Use::DepthAttachment:
        return {kDepthStages,
                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, true, true};
    case Use::DepthResolve:
        // Depth resolves run in the colour-output stage with colour-attachment access
        // (render pass resolve rules); name both so any reading of the spec is covered.
        return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | kDepthStages,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, true, false};
    case Use::DepthTest:
        return {kDepthStages | kShaderStages,
                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, false, true};
    case Use::Sampled:
        return {kShaderStages, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, false, true};
    case Use::StorageRead:
        // The vertex stage too: a vertex shader may pull from a buffer a compute pass wrote
        // (the visibility buffer's hybrid rasterizer, vis_raster_hw.vert).
        return {kShaderStages | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_READ_BIT, VK_IMAGE_LAYOUT_GENERAL, false, true};
    case Use::StorageWrite:
        return {kShaderStages,
                VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                VK_IMAGE_LAYOUT_GENERAL, true, true};
    case Use::TransferSrc:
        return {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, false, true};
    case Use::TransferDst:
        return {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, true, false};
    case Use::IndirectRead:
        return {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT,
                VK_IMAGE_LAYOUT_GENERAL, false, true};
    }
    throw GraphError("unknown Use");
}

bool imageOnly(Use use) {
    return use != Use::StorageRead && use != Use::StorageWrite && use != Use::TransferSrc &&
           use != Use::TransferDst && use != Use::IndirectRead;
}

VkDescriptorType descriptorType(Use use, bool isImage) {
    if (use == Use::Sampled || use == Use::DepthTest)
        return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    return isImage ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

ResourceHandle GraphDecl::addResource(const std::string& name, bool isImage) {
    resources_.push_back({name, isImage});
    return {uint32_t(resources_.size() - 1)};
}

void GraphDecl::addPass(const std::string& name, std::vector<PassUse> uses) {
    // The name is the pass's key for its descriptor set, its timestamps and the report.
    for (const Pass& p : passes_)
        if (p.name == name) throw GraphError("pass '" + name + "' declared twice");
    std::set<uint32_t> bindings;
    for (const PassUse& u : uses) {
        if (u.resource.index >= resources_.size())
            throw GraphError("pass '" + name + "' uses an unknown resource");
        const Resource& r = resources_[u.resource.index];
        if (!r.isImage && imageOnly(u.use))
            throw GraphError("pass '" + name + "' uses buffer '" + r.name + "' as " +
                             useName(u.use) + ", which needs an image");
        if (u.binding == kNoBinding) continue;
        if (!bindable(u.use))
            throw GraphError("pass '" + name + "' binds '" + r.name + "' at binding " +
                             std::to_string(u.binding) + " as " + useName(u.use) +
                             ", which no descriptor can hold");
        if (!bindings.insert(u.binding).second)
            throw GraphError("pass '" + name + "' declares binding " + std::to_string(u.binding) +
                             " twice");
    }
    passes_.push_back({name, std::move(uses)});
}

void GraphDecl::exportResource(const std::string& publicName, ResourceHandle h) {
    if (h.index >= resources_.size())
        throw GraphError("export '" + publicName + "' names an unknown resource");
    resources_[h.index].exported = true;
    exports_.emplace_back(publicName, h);
}

const GraphDecl::Pass& GraphDecl::pass(const std::string& name) const {
    for (const Pass& p : passes_)
        if (p.name == name) return p;
    throw GraphError("no pass named '" + name + "'");
}

void GraphDecl::expectUse(uint32_t pass, ResourceHandle h, Use use) const {
    const Pass& p = passes_.at(pass);
    for (const PassUse& u : p.uses)
        if (u.resource.index == h.index && u.use == use) return;
    const std::string name =
        h.index < resources_.size() ? resources_[h.index].name : "an unknown resource";
    throw GraphError("pass '" + p.name + "' uses '" + name + "' as " + useName(use) +
                     " without declaring it");
}

// Walks the passes backwards from the exports: a pass lives when it writes something needed.
std::vector<bool> GraphDecl::cull() const {
    std::vector<bool> needed(resources_.size()), live(passes_.size());
    for (size_t i = 0; i < resources_.size(); ++i)
        needed[i] = resources_[i].exported;
    for (size_t p = passes_.size(); p-- > 0;) {
        for (const PassUse& u : passes_[p].uses)
            if (useInfo(u.use).writes && needed[u.resource.index]) live[p] = true;
        if (!live[p]) continue;
        for (const PassUse& u : passes_[p].uses)
            needed[u.resource.index] = true;
    }
    return live;
}

// A live pass that only reads a resource no earlier live pass wrote would read the
// previous frame's discarded contents (every frame starts from UNDEFINED): an error.
void GraphDecl::checkReads(const std::vector<bool>& live) const {
    std::vector<bool> written(resources_.size());
    for (size_t p = 0; p < passes_.size(); ++p) {
        if (!live[p]) continue;
        for (const PassUse& u : passes_[p].uses) {
            UseInfo info = useInfo(u.use);
            if (info.reads && !info.writes && !written[u.resource.index])
                throw GraphError("pass '" + passes_[p].name + "' reads '" +
                                 resources_[u.resource.index].name + "' (" + useName(u.use) +
                                 ") before any pass writes it");
        }
        for (const PassUse& u : passes_[p].uses)
            if (useInfo(u.use).writes) written[u.resource.index] = true;
    }
    for (const auto& [name, h] : exports_)
        if (!written[h.index])
            throw GraphError("export '" + name + "' ('" + resources_[h.index].name +
                             "') is never written");
}

GraphPlan GraphDecl::plan() const {
    GraphPlan plan;
    plan.live = cull();
    checkReads(plan.live);
    plan.resources.resize(resources_.size());
    for (const auto& [name, h] : exports_) {
        plan.resources[h.index].imageUsage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        plan.resources[h.index].bufferUsage |= VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    }
    std::vector<State> states(resources_.size());
    for (uint32_t p = 0; p < passes_.size(); ++p) {
        if (!plan.live[p]) continue;
        PlannedPass planned{p, {}};
        for (const PassUse& u : passes_[p].uses) {
            PlannedResource& r = plan.resources[u.resource.index];
            r.allocated = true;
            r.imageUsage |= imageUsage(u.use);
            r.bufferUsage |= bufferUsage(u.use);
            if (r.firstWriter.empty() && useInfo(u.use).writes) r.firstWriter = passes_[p].name;
            transition(u.resource.index, resources_[u.resource.index].isImage, u.use,
                       states[u.resource.index], planned.barriers);
        }
        plan.passes.push_back(std::move(planned));
    }
    for (const auto& [name, h] : exports_)
        transition(h.index, resources_[h.index].isImage, Use::TransferSrc, states[h.index],
                   plan.exportBarriers);
    return plan;
}

} // namespace tp
