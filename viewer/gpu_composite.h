#pragma once
// The scene area composed on the UI's device (issue: no readback to show an image): the split
// view, flip and the difference heat map from the renderers' images where they are (a
// renderer's display copy on the same device, viewer/display_image.h), or from an image on
// the CPU uploaded once (the reference, a renderer on another device). The rules are
// composite.h's; shaders/viewer/composite.comp is their twin. What the composite needs from
// the images is computed beside them: auto exposure's log-average (partial sums per workgroup,
// added on the CPU in double) and the heat map's 99th percentile (an exact radix select over
// the values' bits, two histograms). Only those few words come back, never an image.
// The debug overlays stay composite.h's (their images are read back with the render).
#include <cstdint>
#include <memory>

#include <vulkan/vulkan.h>

#include "core/gpu/descriptors.h"
#include "core/gpu/resources.h"
#include "core/image/image.h"
#include "viewer/composite.h"
#include "viewer/composite_shared.h"

namespace tp::view {

// One side of the composite: a GPU image (RGBA float, SHADER_READ_ONLY_OPTIMAL, on the UI's
// device) or a CPU image; `serial` names its content (an upload is kept per serial).
struct CompositeSide {
    const Image* gpu = nullptr;
    const ImageRGBA* cpu = nullptr;
    uint64_t serial = 0;
    bool present() const { return gpu || cpu; }
    uint32_t width() const { return gpu ? gpu->desc.width : cpu ? cpu->width : 0; }
    uint32_t height() const { return gpu ? gpu->desc.height : cpu ? cpu->height : 0; }
};

class GpuComposite {
  public:
    explicit GpuComposite(GpuContext& ctx);
    ~GpuComposite();
    GpuComposite(const GpuComposite&) = delete;
    GpuComposite& operator=(const GpuComposite&) = delete;

    // autoExposureEv (core/image/tonemap.h) of the side's image, on the GPU.
    float autoExposureEv(const CompositeSide& side);
    // Composes split or difference (in.mode; in.a/in.b/in.overlay are not read: the sides are
    // given here) into bytes() on the GPU, waiting for it. The result's rgba is empty: the
    // bytes stay in bytes(), which the UI copies into its target (swapRB: the target is BGRA).
    Composite compose(const CompositeInput& in, const CompositeSide& a, const CompositeSide& b,
                      uint32_t width, uint32_t height, bool swapRB);
    const Buffer& bytes() const { return out_; }
    // The last compose's bytes, read back (a test's check against composite.h's compose).
    std::vector<uint8_t> readBytes(const Composite& c);

  private:
    const Image& resolve(const CompositeSide& side, int slot);
    void bindSides(const Image& left, const Image& right);
    void dispatch(VkPipeline pipeline, const gpu::CompositePush& push, uint32_t width,
                  uint32_t height, bool stats);
    float percentile99(uint32_t w, uint32_t h); // of the bound sides
    std::vector<uint32_t> histogram(VkPipeline pipeline, gpu::CompositePush push, uint32_t words);

    GpuContext& ctx_;
    VkSampler sampler_ = VK_NULL_HANDLE;
    PassSet composeSet_, statsSet_;
    VkDescriptorSetLayout emptySet_ = VK_NULL_HANDLE;
    VkPipelineLayout composeLayout_ = VK_NULL_HANDLE, statsLayout_ = VK_NULL_HANDLE;
    VkPipeline compose_ = VK_NULL_HANDLE, logLuminance_ = VK_NULL_HANDLE,
               highHistogram_ = VK_NULL_HANDLE, lowHistogram_ = VK_NULL_HANDLE;
    Buffer ramp_, stats_, out_;
    Image placeholder_;      // a bound side that shows nothing
    Image uploaded_[2];      // CPU sides, by slot
    uint64_t uploadedSerial_[2] = {0, 0};
};

} // namespace tp::view
