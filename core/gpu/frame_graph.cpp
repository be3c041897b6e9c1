#include "core/gpu/frame_graph.h"

#include <cstring>

#include "core/gpu/barriers.h"
#include "core/gpu/context.h"
#include "core/gpu/ledger.h"
#include "core/gpu/pass_statistics.h"
#include "core/gpu/profiler.h"
#include "core/gpu/vk_check.h"

namespace tp {

const Image& PassContext::image(ResourceHandle h) const {
    return graph.image(h);
}
const Buffer& PassContext::buffer(ResourceHandle h) const {
    return graph.buffer(h);
}
void PassContext::expectUse(ResourceHandle h, Use use) const {
    if (pass != ~0u) graph.declarations().expectUse(pass, h, use);
}

FrameGraph::FrameGraph(GpuContext& ctx, std::string owner, uint32_t width, uint32_t height)
    : ctx_(ctx), owner_(std::move(owner)), width_(width), height_(height) {}

FrameGraph::~FrameGraph() = default;

// The plan is made once from everything declared: a later declaration would not be in it.
void FrameGraph::checkOpen(const std::string& what) const {
    if (compiled_) throw GraphError(owner_ + ": " + what + " after the frame graph was compiled");
}

ResourceHandle FrameGraph::createImage(const std::string& name, const GraphImageInfo& info) {
    checkOpen("image '" + name + "' declared");
    resources_.push_back({info, 0, info.purpose, {}, {}});
    return decl_.addResource(name, true);
}

ResourceHandle FrameGraph::createBuffer(const std::string& name, VkDeviceSize size,
                                        const std::string& purpose) {
    checkOpen("buffer '" + name + "' declared");
    ResourceNode node;
    node.bufferSize = size;
    node.purpose = purpose;
    resources_.push_back(std::move(node));
    return decl_.addResource(name, false);
}

void FrameGraph::addPass(const std::string& name, std::vector<PassUse> uses,
                         std::function<void(PassContext&)> execute) {
    checkOpen("pass '" + name + "' added");
    decl_.addPass(name, std::move(uses));
    executes_.push_back(std::move(execute));
}

void FrameGraph::exportResource(const std::string& publicName, ResourceHandle h) {
    checkOpen("export '" + publicName + "' added");
    decl_.exportResource(publicName, h);
}

void FrameGraph::watchAfterFrame(ResourceHandle h, VkDeviceSize offset, VkDeviceSize size) {
    const std::string& name = decl_.resources().at(h.index).name;
    checkOpen("watch of '" + name + "' added");
    if (!decl_.resources()[h.index].exported) decl_.exportResource(name, h);
    watches_.push_back({h, offset, size, 0});
}

std::vector<uint8_t> FrameGraph::watched(ResourceHandle h) const {
    for (const Watch& w : watches_) {
        if (w.buffer.index != h.index || !isAllocated(h)) continue;
        const uint8_t* at = static_cast<const uint8_t*>(watchBuffer_.mapped) + w.at;
        return std::vector<uint8_t>(at, at + w.size);
    }
    return {};
}

void FrameGraph::compile() {
    plan_ = decl_.plan();
    checkImagesSupported();
    allocate();
    compiled_ = true;
}

ImageDesc FrameGraph::imageDesc(uint32_t i) const {
    const ResourceNode& r = resources_[i];
    ImageDesc desc;
    desc.format = r.imageInfo.format;
    desc.width = r.imageInfo.width ? r.imageInfo.width : width_;
    desc.height = r.imageInfo.height ? r.imageInfo.height : height_;
    desc.samples = r.imageInfo.samples;
    desc.usage = plan_.resources[i].imageUsage | r.imageInfo.extraUsage;
    return desc;
}

// The sample counts an image may be created with depend on its format and usage
// (VkImageFormatProperties::sampleCounts), not only on the framebuffer limits the CLI checks:
// a storage or float image may allow fewer. Every image is checked before any is created, so
// an unsupported combination is one line naming the image, never a validation error or a
// half-allocated graph.
void FrameGraph::checkImagesSupported() const {
    for (uint32_t i = 0; i < resources_.size(); ++i) {
        if (!plan_.resources[i].allocated || !decl_.resources()[i].isImage) continue;
        const ImageDesc d = imageDesc(i);
        if (Status s = checkImageSupported(ctx_, d); !s)
            throw GraphError("image '" + decl_.resources()[i].name + "': " + s.error());
    }
}

// Allocates what the live passes touch, with the union of their usages.
void FrameGraph::allocate() {
    for (uint32_t i = 0; i < resources_.size(); ++i) {
        const PlannedResource& p = plan_.resources[i];
        if (!p.allocated) continue;
        ResourceNode& r = resources_[i];
        const GraphDecl::Resource& d = decl_.resources()[i];
        LedgerTag tag{owner_, p.firstWriter, d.name, r.purpose};
        if (d.isImage) {
            r.image = tp::createImage(ctx_, imageDesc(i), tag);
        } else {
            r.buffer = tp::createBuffer(ctx_, r.bufferSize, p.bufferUsage, MemoryKind::Device, tag);
        }
    }
    VkDeviceSize total = 0;
    for (Watch& w : watches_) {
        if (!isAllocated(w.buffer)) continue;
        if (w.offset + w.size > resources_[w.buffer.index].bufferSize)
            throw GraphError("watch of '" + decl_.resources()[w.buffer.index].name +
                             "' reaches past the buffer");
        w.at = total;
        total += (w.size + 15) / 16 * 16;
    }
    if (total == 0) return;
    watchBuffer_ = tp::createBuffer(ctx_, total, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                    MemoryKind::Readback,
                                    {owner_, "", "frame_watch",
                                     "what the host reads after each frame (overflow counts)"});
    std::memset(watchBuffer_.mapped, 0, total);
}

// After the export barriers (the watched buffers are exported: TRANSFER_SRC by now).
void FrameGraph::recordWatches(VkCommandBuffer cmd) const {
    if (!watchBuffer_.buffer) return;
    for (const Watch& w : watches_) {
        if (!isAllocated(w.buffer)) continue;
        VkBufferCopy copy{w.offset, w.at, w.size};
        vkCmdCopyBuffer(cmd, resources_[w.buffer.index].buffer.buffer, watchBuffer_.buffer, 1, &copy);
    }
    // The copies' writes become visible to the host's read after the frame's wait.
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

PassSet FrameGraph::createPassSet(const std::string& pass, VkSampler sampler,
                                  const std::vector<ExternalBuffer>& externals) const {
    if (!compiled_) throw GraphError("pass '" + pass + "': descriptor set made before compile");
    const GraphDecl::Pass& p = decl_.pass(pass);
    std::vector<SetBinding> bindings;
    for (const PassUse& u : p.uses) {
        if (u.binding == kNoBinding) continue;
        if (!isAllocated(u.resource))
            throw GraphError("pass '" + pass + "' is culled: it has no descriptor set");
        bindings.push_back(
            {u.binding, descriptorType(u.use, decl_.resources()[u.resource.index].isImage)});
    }
    for (const ExternalBuffer& e : externals)
        bindings.push_back({e.binding, e.type});
    // Every check before anything is created (a PassSet owns nothing until it is destroyed).
    for (size_t i = 0; i < bindings.size(); ++i) {
        for (size_t j = 0; j < i; ++j)
            if (bindings[j].binding == bindings[i].binding)
                throw GraphError("pass '" + pass + "': binding " +
                                 std::to_string(bindings[i].binding) +
                                 " is given twice (a use and an external buffer)");
        if (bindings[i].type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER && !sampler)
            throw GraphError("pass '" + pass + "' samples binding " +
                             std::to_string(bindings[i].binding) + " but was given no sampler");
    }
    PassSet set = tp::createPassSet(ctx_, bindings);
    set.pass = pass;
    set.bindings = bindings;
    for (const PassUse& u : p.uses) {
        if (u.binding == kNoBinding) continue;
        const VkDescriptorType type =
            descriptorType(u.use, decl_.resources()[u.resource.index].isImage);
        if (type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER) {
            writeBufferDescriptor(ctx_, set.set, u.binding, buffer(u.resource).buffer);
        } else {
            VkSampler s =
                type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER ? sampler : VK_NULL_HANDLE;
            writeImageDescriptor(ctx_, set.set, u.binding, type, image(u.resource).view,
                                 useInfo(u.use).layout, s);
        }
    }
    for (const ExternalBuffer& e : externals)
        writeBufferDescriptor(ctx_, set.set, e.binding, e.buffer, e.type);
    return set;
}

void FrameGraph::recordBarrier(VkCommandBuffer cmd, const PlanBarrier& b) const {
    const ResourceNode& r = resources_[b.resource];
    if (b.image) {
        const VkFormat f = r.image.desc.format;
        imageBarrier(cmd, r.image.image, attachmentLayout(f, b.oldLayout),
                     attachmentLayout(f, b.newLayout), b.srcStages, b.srcAccess, b.dstStages,
                     b.dstAccess, {r.image.aspect, 0, 1, 0, 1});
        return;
    }
    VkBufferMemoryBarrier2 bb{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
    bb.srcStageMask = b.srcStages;
    bb.srcAccessMask = b.srcAccess;
    bb.dstStageMask = b.dstStages;
    bb.dstAccessMask = b.dstAccess;
    bb.srcQueueFamilyIndex = bb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    bb.buffer = r.buffer.buffer;
    bb.size = VK_WHOLE_SIZE;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.bufferMemoryBarrierCount = 1;
    dep.pBufferMemoryBarriers = &bb;
    vkCmdPipelineBarrier2(cmd, &dep);
}

void FrameGraph::record(VkCommandBuffer cmd, GpuProfiler* profiler, PassStatistics* statistics) {
    if (!compiled_) throw GraphError("FrameGraph::record before compile");
    for (const PlannedPass& p : plan_.passes) {
        for (const PlanBarrier& b : p.barriers)
            recordBarrier(cmd, b);
        const std::string& name = decl_.passes()[p.pass].name;
        // The query brackets the timed scope: its own cost stays out of the pass's time.
        const uint32_t query = statistics ? statistics->begin(cmd, name) : ~0u;
        uint32_t scope = profiler ? profiler->beginScope(cmd, name) : 0;
        PassContext pc{cmd, *this, p.pass};
        executes_[p.pass](pc);
        if (profiler) profiler->endScope(cmd, scope);
        if (statistics) statistics->end(cmd, query);
    }
    for (const PlanBarrier& b : plan_.exportBarriers)
        recordBarrier(cmd, b);
    recordWatches(cmd);
}

const Image& FrameGraph::image(ResourceHandle h) const {
    const ResourceNode& r = resources_.at(h.index);
    if (!decl_.resources()[h.index].isImage || !r.image.image)
        throw GraphError("resource '" + decl_.resources()[h.index].name +
                         "' is not an allocated image");
    return r.image;
}

const Buffer& FrameGraph::buffer(ResourceHandle h) const {
    const ResourceNode& r = resources_.at(h.index);
    if (decl_.resources()[h.index].isImage || !r.buffer.buffer)
        throw GraphError("resource '" + decl_.resources()[h.index].name +
                         "' is not an allocated buffer");
    return r.buffer;
}

uint64_t FrameGraph::contentBytes(uint32_t resource) const {
    if (!decl_.resources().at(resource).isImage) return resources_.at(resource).bufferSize;
    const ImageDesc d = imageDesc(resource);
    return uint64_t(d.width) * d.height * uint32_t(d.samples) * formatBytesPerTexel(d.format);
}

VkSampleCountFlagBits FrameGraph::samples(uint32_t resource) const {
    return decl_.resources().at(resource).isImage ? resources_.at(resource).imageInfo.samples : VK_SAMPLE_COUNT_1_BIT;
}

VkFormat FrameGraph::format(uint32_t resource) const {
    return decl_.resources().at(resource).isImage ? resources_.at(resource).imageInfo.format
                                                  : VK_FORMAT_UNDEFINED;
}

bool FrameGraph::isAllocated(ResourceHandle h) const {
    const ResourceNode& r = resources_.at(h.index);
    return decl_.resources()[h.index].isImage ? r.image.image != VK_NULL_HANDLE
                                              : r.buffer.buffer != VK_NULL_HANDLE;
}

ResourceHandle FrameGraph::exported(const std::string& publicName) const {
    for (const auto& [name, h] : decl_.exports())
        if (name == publicName) return h;
    return {};
}

std::vector<std::string> FrameGraph::livePasses() const {
    std::vector<std::string> out;
    for (size_t i = 0; i < decl_.passes().size(); ++i)
        if (compiled_ && plan_.live[i]) out.push_back(decl_.passes()[i].name);
    return out;
}

std::vector<std::string> FrameGraph::culledPasses() const {
    std::vector<std::string> out;
    for (size_t i = 0; i < decl_.passes().size(); ++i)
        if (!compiled_ || !plan_.live[i]) out.push_back(decl_.passes()[i].name);
    return out;
}

} // namespace tp
