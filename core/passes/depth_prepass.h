#pragma once
// The depth prepass, one implementation for every pipeline that has one (Forward+, multipass
// forward): depth only for opaque draws, the alpha test of every other pass for masked ones
// (prepass_mask.frag), blended draws left out. After it every shading pass tests EQUAL, so
// each sample is shaded once per light however deep the scene is.
//
// The rate of the masked alpha test under MSAA is a parameter, not a guess from the shader:
//   Pixel   one invocation per pixel with inputs at the centre: the pixel's samples share one
//           alpha and so one coverage (Forward+).
//   Sample  the test per sample, as the reference: the same interpolants per sample, the
//           same coverage (multipass forward).
// Both render the same depth for opaque draws; they part only at masked edges under MSAA.
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/frame_graph.h"

namespace tp {
class GpuContext;
class SceneGpu;
struct DrawItem;
} // namespace tp

namespace tp::passes {

enum class MaskedRate { Pixel, Sample };

struct DepthPrepassParams {
    uint32_t samples = 1;
    MaskedRate maskedRate = MaskedRate::Sample;
    std::vector<const DrawItem*> opaque, masked; // the draws it records, in this order
};

// depth: the attachment (per sample under MSAA); resolve: the single-sample depth it resolves
// into (sample 0) under MSAA, invalid at 1x.
struct DepthPrepassTargets {
    ResourceHandle depth, resolve;
};

class DepthPrepass {
  public:
    DepthPrepass(GpuContext& ctx, const SceneGpu& scene, DepthPrepassParams params);
    ~DepthPrepass();
    DepthPrepass(const DepthPrepass&) = delete;
    DepthPrepass& operator=(const DepthPrepass&) = delete;
    // Declares pass "depth_prepass": writes `t.depth`, resolves into `t.resolve`.
    void plan(FrameGraph& graph, DepthPrepassTargets t);
    // Pipelines (after the graph is compiled; they depend on no resource).
    void prepare();
    uint32_t draws() const { return draws_; } // recorded in the last frame
    bool hasMaskedPipeline() const { return masked_ != VK_NULL_HANDLE; }

  private:
    void record(PassContext& pc);
    GpuContext& ctx_;
    const SceneGpu& scene_;
    DepthPrepassParams params_;
    DepthPrepassTargets t_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline opaque_ = VK_NULL_HANDLE, masked_ = VK_NULL_HANDLE;
    uint32_t draws_ = 0;
};

} // namespace tp::passes
