#pragma once
// A small frame graph. A pass declares every image and buffer it reads and writes (and how:
// attachment, sampled, storage, transfer) before anything is recorded; from those
// declarations the graph
//   - culls passes whose outputs nobody reads (the exported outputs are the roots),
//   - allocates the transient resources the live passes use (tagged in the ledger with the
//     owner and the pass that first writes them), with usage flags from the declarations,
//   - records the barriers (synchronization2) between uses, and
//   - wraps every pass in GPU timestamps.
// The graph is built once per configuration and recorded once; the command buffer can be
// submitted repeatedly (every frame starts by discarding the previous frame's contents).
#include <functional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/resources.h"

namespace tp {

class GpuContext;
class GpuProfiler;

enum class Use {
    ColorAttachment, // written (and read by blending)
    ColorResolve,    // MSAA colour resolve target
    DepthAttachment, // depth test and write
    DepthResolve,    // MSAA depth resolve target
    DepthTest,       // depth test without writes; may be sampled in the same pass
    Sampled,         // sampled or texelFetch'd in fragment/compute shaders
    StorageRead,
    StorageWrite,    // write-only or read-write storage access
    TransferSrc,
    TransferDst,
};

struct ResourceHandle {
    uint32_t index = ~0u;
    bool valid() const { return index != ~0u; }
};

struct GraphImageInfo {
    VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
    uint32_t width = 0, height = 0; // 0 = the frame's extent
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    std::string purpose;
};

class FrameGraph;

struct PassContext {
    VkCommandBuffer cmd;
    FrameGraph& graph;
    const Image& image(ResourceHandle h) const;
    const Buffer& buffer(ResourceHandle h) const;
};

struct PassUse {
    ResourceHandle resource;
    Use use;
};

class FrameGraph {
  public:
    FrameGraph(GpuContext& ctx, std::string owner, uint32_t width, uint32_t height);
    ~FrameGraph();

    ResourceHandle createImage(const std::string& name, const GraphImageInfo& info);
    ResourceHandle createBuffer(const std::string& name, VkDeviceSize size, const std::string& purpose);
    void addPass(const std::string& name, std::vector<PassUse> uses,
                 std::function<void(PassContext&)> execute);
    // An output read after the frame (readback, report): left in TRANSFER_SRC layout/access.
    void exportResource(const std::string& publicName, ResourceHandle h);

    void compile();                                   // cull, allocate
    void record(VkCommandBuffer cmd, GpuProfiler* profiler); // barriers, timestamps, passes

    const Image& image(ResourceHandle h) const;
    const Buffer& buffer(ResourceHandle h) const;
    ResourceHandle exported(const std::string& publicName) const;
    bool isAllocated(ResourceHandle h) const;
    std::vector<std::string> livePasses() const;
    std::vector<std::string> culledPasses() const;
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    const std::string& owner() const { return owner_; }

  private:
    struct ResourceNode;
    struct PassNode;
    struct State;
    void barrier(VkCommandBuffer cmd, uint32_t resource, Use use, std::vector<State>& states);

    GpuContext& ctx_;
    std::string owner_;
    uint32_t width_, height_;
    std::vector<ResourceNode> resources_;
    std::vector<PassNode> passes_;
    std::vector<std::pair<std::string, ResourceHandle>> exports_;
    bool compiled_ = false;
};

} // namespace tp
