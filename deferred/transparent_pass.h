#pragma once
// The hybrid forward pass: blended draws, back to front, alpha-blended into hdr (into every
// covered sample of hdr_msaa, then resolved, under MSAA), lit from the per-tile transparent
// light lists; shaded once per pixel at --msaa-shading pixel and per sample at sample
// (DeferredTargets::blendedPerPixel). Planned only when the scene has blended materials.
#include "core/gpu/frame_graph.h"
#include "deferred/deferred_targets.h"
#include "core/gpu/descriptors.h"
#include "core/gpu/resources.h"

namespace tp {

class GpuContext;
class SceneGpu;

class TransparentPass {
  public:
    TransparentPass(GpuContext& ctx, SceneGpu& scene) : ctx_(ctx), scene_(scene) {}
    ~TransparentPass();
    // slices > 0 with `masks` (--light-assign clustered): fragments take their cluster's
    // lights through the slice rows the tiled pass wrote over the transparent lists.
    // blendBounds: the blended depth bounds (clustered: where each tile's front slices start).
    void plan(FrameGraph& graph, DeferredTargets& t, ResourceHandle blendBounds, uint32_t slices = 0,
              ResourceHandle masks = {});
    // candidates: the tiled pass's light_candidates; binned: the transparent lists are
    // bitmasks over them (deferred_shared.h: defMaskRowsBase).
    void prepare(FrameGraph& graph, VkBuffer candidates, bool binned);

  private:
    void record(PassContext& pc);
    GpuContext& ctx_;
    SceneGpu& scene_;
    const DeferredTargets* t_ = nullptr;
    uint32_t slices_ = 0;
    ResourceHandle masks_;
    Buffer noMasks_; // tiled: a 16-byte stand-in for the unused slice rows
    PassSet set_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

} // namespace tp
