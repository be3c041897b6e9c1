#pragma once
// A small frame graph. A pass declares every image and buffer it reads and writes (and how:
// attachment, sampled, storage, transfer) before anything is recorded; from those
// declarations the graph
//   - culls passes whose outputs nobody reads (the exported outputs are the roots),
//   - allocates the transient resources the live passes use (tagged in the ledger with the
//     owner and the pass that first writes them), with usage flags from the declarations,
//   - records the barriers (synchronization2) between uses, and
//   - wraps every pass in GPU timestamps.
// The planning (culling, checks, barriers as data) is GraphDecl::plan() in graph_plan.h,
// which needs no device; this class allocates and records from its plan.
// The graph is built once per configuration and recorded once; the command buffer can be
// submitted repeatedly (every frame starts by discarding the previous frame's contents).
#include <functional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/descriptors.h"
#include "core/gpu/graph_plan.h"
#include "core/gpu/resources.h"

namespace tp {

class GpuContext;
class GpuProfiler;
class PassStatistics;

struct GraphImageInfo {
    VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
    uint32_t width = 0, height = 0; // 0 = the frame's extent
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    std::string purpose;
    // Usage beyond what the declared uses give: an image a pass both renders and samples
    // between its own renderings (ShadowMaps' PerLight map), which one Use cannot say.
    VkImageUsageFlags extraUsage = 0;
};

class FrameGraph;

struct PassContext {
    VkCommandBuffer cmd;
    FrameGraph& graph;
    const Image& image(ResourceHandle h) const;
    const Buffer& buffer(ResourceHandle h) const;
    uint32_t pass = ~0u; // the pass being recorded (~0u: none, nothing is checked)
    // Throws GraphError unless the pass declared this use (beginRendering's attachments).
    void expectUse(ResourceHandle h, Use use) const;
};

// A buffer bound in a pass's set that the graph does not track: static data uploaded once,
// before any frame, so no barrier is needed between frames. A storage buffer unless `type`
// says otherwise (Forward+ binds its lights as a uniform buffer on lavapipe).
struct ExternalBuffer {
    uint32_t binding;
    VkBuffer buffer;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
};

class FrameGraph {
  public:
    FrameGraph(GpuContext& ctx, std::string owner, uint32_t width, uint32_t height);
    ~FrameGraph();

    ResourceHandle createImage(const std::string& name, const GraphImageInfo& info);
    ResourceHandle createBuffer(const std::string& name, VkDeviceSize size,
                                const std::string& purpose);
    void addPass(const std::string& name, std::vector<PassUse> uses,
                 std::function<void(PassContext&)> execute);
    // An output read after the frame (readback, report): left in TRANSFER_SRC layout/access.
    void exportResource(const std::string& publicName, ResourceHandle h);
    // A buffer range the host reads after every frame (a capacity's overflow count): exported,
    // and copied at the end of the recording into a host-visible buffer of the graph's, so the
    // read after a view's frames needs no submission and wait of its own (issue 42).
    void watchAfterFrame(ResourceHandle buffer, VkDeviceSize offset, VkDeviceSize size);
    // The watched range as the last completed frame left it; empty when the buffer is not
    // allocated (its passes culled) or was not watched.
    std::vector<uint8_t> watched(ResourceHandle buffer) const;

    // The pass's descriptor set (set TP_SET_PASS) from its uses that carry a binding: layout,
    // descriptor types and writes (images in the layout of their use, sampled ones with
    // `sampler`). After compile; the pass must be live.
    PassSet createPassSet(const std::string& pass, VkSampler sampler = VK_NULL_HANDLE,
                          const std::vector<ExternalBuffer>& externals = {}) const;

    void compile(); // plan (cull, check, barriers), allocate
    // Barriers, timestamps and (with `statistics`) a pipeline-statistics query per pass, passes.
    void record(VkCommandBuffer cmd, GpuProfiler* profiler, PassStatistics* statistics = nullptr);

    const Image& image(ResourceHandle h) const;
    const Buffer& buffer(ResourceHandle h) const;
    ResourceHandle exported(const std::string& publicName) const;
    bool isAllocated(ResourceHandle h) const;
    // What one pass over the resource touches: texels x samples x bytes per texel for an image,
    // the size for a buffer (docs/efficiency.md: the bytes a pass is counted to move).
    uint64_t contentBytes(uint32_t resource) const;
    VkSampleCountFlagBits samples(uint32_t resource) const; // 1 for a buffer
    VkFormat format(uint32_t resource) const;               // UNDEFINED for a buffer
    std::vector<std::string> livePasses() const;
    std::vector<std::string> culledPasses() const;
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    const std::string& owner() const { return owner_; }

    const GraphPlan& plan() const { return plan_; }
    const GraphDecl& declarations() const { return decl_; }

  private:
    struct ResourceNode {
        GraphImageInfo imageInfo;
        VkDeviceSize bufferSize = 0;
        std::string purpose;
        Image image;
        Buffer buffer;
    };
    void checkOpen(const std::string& what) const;
    ImageDesc imageDesc(uint32_t resource) const; // after plan_: the union of its usages
    void checkImagesSupported() const;
    void allocate();
    void recordBarrier(VkCommandBuffer cmd, const PlanBarrier& b) const;
    void recordWatches(VkCommandBuffer cmd) const;

    struct Watch {
        ResourceHandle buffer;
        VkDeviceSize offset = 0, size = 0;
        VkDeviceSize at = 0; // where in watchBuffer_
    };

    GpuContext& ctx_;
    std::string owner_;
    uint32_t width_, height_;
    GraphDecl decl_;
    GraphPlan plan_;
    std::vector<ResourceNode> resources_;
    std::vector<std::function<void(PassContext&)>> executes_;
    std::vector<Watch> watches_;
    Buffer watchBuffer_; // host-visible: the watches' bytes after each frame
    bool compiled_ = false;
};

} // namespace tp
