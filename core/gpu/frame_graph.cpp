#include "core/gpu/frame_graph.h"

#include <stdexcept>

#include "core/gpu/context.h"
#include "core/gpu/profiler.h"
#include "core/gpu/vk_check.h"

namespace tp {

struct FrameGraph::ResourceNode {
    std::string name;
    bool isImage = true;
    GraphImageInfo imageInfo;
    VkDeviceSize bufferSize = 0;
    std::string purpose;
    bool needed = false;
    bool exported = false;
    Image image;
    Buffer buffer;
};

struct FrameGraph::PassNode {
    std::string name;
    std::vector<PassUse> uses;
    std::function<void(PassContext&)> execute;
    bool live = false;
};

// Where a resource stands between uses while recording.
struct FrameGraph::State {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkAccessFlags2 access = VK_ACCESS_2_MEMORY_WRITE_BIT; // unknown work of the previous frame
    bool lastWasWrite = true;
};

namespace {

struct UseInfo {
    VkPipelineStageFlags2 stages;
    VkAccessFlags2 access;
    VkImageLayout layout;
    bool writes;
    bool reads;
};

constexpr VkPipelineStageFlags2 kShaderStages =
    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags2 kDepthStages =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;

UseInfo useInfo(Use use) {
    switch (use) {
    case Use::ColorAttachment:
        return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, true, true};
    case Use::ColorResolve:
        return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, true, false};
    case Use::DepthAttachment:
        return {kDepthStages,
                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, true, true};
    case Use::DepthResolve:
        // Depth resolves run in the colour-output stage with colour-attachment access
        // (render pass resolve rules); name both so any reading of the spec is covered.
        return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | kDepthStages,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, true, false};
    case Use::DepthTest:
        return {kDepthStages | kShaderStages,
                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, false, true};
    case Use::Sampled:
        return {kShaderStages, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL,
                false, true};
    case Use::StorageRead:
        return {kShaderStages, VK_ACCESS_2_SHADER_STORAGE_READ_BIT, VK_IMAGE_LAYOUT_GENERAL, false, true};
    case Use::StorageWrite:
        return {kShaderStages, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                VK_IMAGE_LAYOUT_GENERAL, true, true};
    case Use::TransferSrc:
        return {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, false, true};
    case Use::TransferDst:
        return {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, true, false};
    }
    throw std::logic_error("unknown Use");
}

VkImageUsageFlags imageUsage(Use use, VkFormat format) {
    switch (use) {
    case Use::ColorAttachment:
    case Use::ColorResolve: return VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    case Use::DepthAttachment:
    case Use::DepthResolve:
    case Use::DepthTest: return VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    case Use::Sampled: return VK_IMAGE_USAGE_SAMPLED_BIT;
    case Use::StorageRead:
    case Use::StorageWrite: return VK_IMAGE_USAGE_STORAGE_BIT;
    case Use::TransferSrc: return VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    case Use::TransferDst: return VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    }
    (void)format;
    return 0;
}

VkBufferUsageFlags bufferUsage(Use use) {
    switch (use) {
    case Use::TransferSrc: return VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    case Use::TransferDst: return VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    default: return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    }
}

} // namespace

const Image& PassContext::image(ResourceHandle h) const { return graph.image(h); }
const Buffer& PassContext::buffer(ResourceHandle h) const { return graph.buffer(h); }

FrameGraph::FrameGraph(GpuContext& ctx, std::string owner, uint32_t width, uint32_t height)
    : ctx_(ctx), owner_(std::move(owner)), width_(width), height_(height) {}

FrameGraph::~FrameGraph() = default;

ResourceHandle FrameGraph::createImage(const std::string& name, const GraphImageInfo& info) {
    ResourceNode node;
    node.name = name;
    node.isImage = true;
    node.imageInfo = info;
    node.purpose = info.purpose;
    resources_.push_back(std::move(node));
    return {uint32_t(resources_.size() - 1)};
}

ResourceHandle FrameGraph::createBuffer(const std::string& name, VkDeviceSize size,
                                        const std::string& purpose) {
    ResourceNode node;
    node.name = name;
    node.isImage = false;
    node.bufferSize = size;
    node.purpose = purpose;
    resources_.push_back(std::move(node));
    return {uint32_t(resources_.size() - 1)};
}

void FrameGraph::addPass(const std::string& name, std::vector<PassUse> uses,
                         std::function<void(PassContext&)> execute) {
    for (const PassUse& u : uses)
        if (u.resource.index >= resources_.size())
            throw std::logic_error("pass " + name + " uses an unknown resource");
    passes_.push_back({name, std::move(uses), std::move(execute), false});
}

void FrameGraph::exportResource(const std::string& publicName, ResourceHandle h) {
    resources_.at(h.index).exported = true;
    exports_.emplace_back(publicName, h);
}

void FrameGraph::compile() {
    // Cull: walk passes backwards from the exported resources.
    for (ResourceNode& r : resources_) r.needed = r.exported;
    for (auto it = passes_.rbegin(); it != passes_.rend(); ++it) {
        for (const PassUse& u : it->uses)
            if (useInfo(u.use).writes && resources_[u.resource.index].needed) it->live = true;
        if (!it->live) continue;
        for (const PassUse& u : it->uses)
            if (useInfo(u.use).reads || useInfo(u.use).writes) resources_[u.resource.index].needed = true;
    }
    // Allocate what the live passes touch, with the union of their usages.
    for (uint32_t i = 0; i < resources_.size(); ++i) {
        ResourceNode& r = resources_[i];
        VkImageUsageFlags iu = r.exported ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0;
        VkBufferUsageFlags bu = r.exported ? VK_BUFFER_USAGE_TRANSFER_SRC_BIT : 0;
        std::string firstWriter;
        bool used = false;
        for (const PassNode& p : passes_) {
            if (!p.live) continue;
            for (const PassUse& u : p.uses) {
                if (u.resource.index != i) continue;
                used = true;
                iu |= imageUsage(u.use, r.imageInfo.format);
                bu |= bufferUsage(u.use);
                if (firstWriter.empty() && useInfo(u.use).writes) firstWriter = p.name;
            }
        }
        if (!used) continue;
        LedgerTag tag{owner_, firstWriter, r.name, r.purpose};
        if (r.isImage) {
            ImageDesc d;
            d.format = r.imageInfo.format;
            d.width = r.imageInfo.width ? r.imageInfo.width : width_;
            d.height = r.imageInfo.height ? r.imageInfo.height : height_;
            d.samples = r.imageInfo.samples;
            d.usage = iu;
            r.image = tp::createImage(ctx_, d, tag);
        } else {
            r.buffer = tp::createBuffer(ctx_, r.bufferSize, bu, MemoryKind::Device, tag);
        }
    }
    compiled_ = true;
}

void FrameGraph::barrier(VkCommandBuffer cmd, uint32_t index, Use use, std::vector<State>& states) {
    ResourceNode& r = resources_[index];
    State& s = states[index];
    UseInfo u = useInfo(use);
    bool layoutChange = r.isImage && s.layout != u.layout;
    if (!layoutChange && !u.writes && !s.lastWasWrite) {
        // Read after read: no barrier, but a later write must wait for this reader too.
        s.stages |= u.stages;
        s.access |= u.access;
        return;
    }
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    VkImageMemoryBarrier2 ib{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    VkBufferMemoryBarrier2 bb{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
    VkAccessFlags2 srcAccess = s.lastWasWrite ? s.access : VkAccessFlags2(0);
    if (r.isImage) {
        ib.srcStageMask = s.stages;
        ib.srcAccessMask = srcAccess;
        ib.dstStageMask = u.stages;
        ib.dstAccessMask = u.access;
        ib.oldLayout = s.layout;
        ib.newLayout = u.layout;
        ib.srcQueueFamilyIndex = ib.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        ib.image = r.image.image;
        ib.subresourceRange = {r.image.aspect, 0, 1, 0, 1};
        dep.imageMemoryBarrierCount = 1;
        dep.pImageMemoryBarriers = &ib;
    } else {
        bb.srcStageMask = s.stages;
        bb.srcAccessMask = srcAccess;
        bb.dstStageMask = u.stages;
        bb.dstAccessMask = u.access;
        bb.srcQueueFamilyIndex = bb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        bb.buffer = r.buffer.buffer;
        bb.size = VK_WHOLE_SIZE;
        dep.bufferMemoryBarrierCount = 1;
        dep.pBufferMemoryBarriers = &bb;
    }
    vkCmdPipelineBarrier2(cmd, &dep);
    s = {u.layout, u.stages, u.access, u.writes};
}

void FrameGraph::record(VkCommandBuffer cmd, GpuProfiler* profiler) {
    if (!compiled_) throw std::logic_error("FrameGraph::record before compile");
    // Every frame starts from "unknown contents, written by the previous frame": images go
    // from UNDEFINED (their contents are discarded), and the first use waits on all commands.
    std::vector<State> states(resources_.size());
    for (PassNode& p : passes_) {
        if (!p.live) continue;
        for (const PassUse& u : p.uses) barrier(cmd, u.resource.index, u.use, states);
        uint32_t scope = profiler ? profiler->beginScope(cmd, p.name) : 0;
        PassContext pc{cmd, *this};
        p.execute(pc);
        if (profiler) profiler->endScope(cmd, scope);
    }
    for (const auto& [name, h] : exports_) barrier(cmd, h.index, Use::TransferSrc, states);
}

const Image& FrameGraph::image(ResourceHandle h) const {
    const ResourceNode& r = resources_.at(h.index);
    if (!r.isImage || !r.image.image) throw std::logic_error("resource " + r.name + " is not an allocated image");
    return r.image;
}

const Buffer& FrameGraph::buffer(ResourceHandle h) const {
    const ResourceNode& r = resources_.at(h.index);
    if (r.isImage || !r.buffer.buffer) throw std::logic_error("resource " + r.name + " is not an allocated buffer");
    return r.buffer;
}

bool FrameGraph::isAllocated(ResourceHandle h) const {
    const ResourceNode& r = resources_.at(h.index);
    return r.isImage ? r.image.image != VK_NULL_HANDLE : r.buffer.buffer != VK_NULL_HANDLE;
}

ResourceHandle FrameGraph::exported(const std::string& publicName) const {
    for (const auto& [name, h] : exports_)
        if (name == publicName) return h;
    return {};
}

std::vector<std::string> FrameGraph::livePasses() const {
    std::vector<std::string> out;
    for (const PassNode& p : passes_)
        if (p.live) out.push_back(p.name);
    return out;
}

std::vector<std::string> FrameGraph::culledPasses() const {
    std::vector<std::string> out;
    for (const PassNode& p : passes_)
        if (!p.live) out.push_back(p.name);
    return out;
}

} // namespace tp
