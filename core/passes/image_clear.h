#pragma once
// A colour image set to one value by compute, before the render pass that would have cleared
// it (shaders/passes/image_clear.comp). A render pass's clear is not free on every device: on
// the H200 it runs on the few SMs that run graphics, about 55 GB/s (0.15 ms for an R32 image
// at 1080p, 0.59 ms at 4x; docs/efficiency.md, "Clears"); a compute pass writes the same
// values on all of them. Where the device cannot store to the image (its format, or a
// multisampled image without shaderStorageImageMultisample), and on a CPU device, plan() adds
// nothing and says so: the render pass clears it as before. On lavapipe that clear is a memset
// and the compute pass measured slower (1280x720: 5.5-7.1 ms an image, the passes it spared no
// faster).
#include <string>

#include <vulkan/vulkan.h>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"

namespace tp {
class GpuContext;

class ImageClear {
  public:
    // onCpuDevice: by compute on a CPU device too (tests: the pass itself, with validation).
    explicit ImageClear(GpuContext& ctx, bool onCpuDevice = false)
        : ctx_(ctx), onCpuDevice_(onCpuDevice) {}
    ~ImageClear();
    ImageClear(const ImageClear&) = delete;
    ImageClear& operator=(const ImageClear&) = delete;

    // Adds pass `name` setting every sample of the graph's image `image` to `value`; false (no
    // pass) where the device cannot store to it or is a CPU: the caller's render pass clears.
    bool plan(FrameGraph& graph, const std::string& name, ResourceHandle image,
              VkClearColorValue value);
    bool planned() const { return !name_.empty(); } // plan() added the pass
    void prepare(FrameGraph& graph);                // nothing if plan() added no pass

  private:
    void record(PassContext& pc);
    GpuContext& ctx_;
    bool onCpuDevice_ = false;
    std::string name_, shader_;
    uint32_t samples_ = 1;
    VkClearColorValue value_{};
    PassSet set_;
    VkDescriptorSetLayout empty_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

} // namespace tp
