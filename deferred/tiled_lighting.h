#pragma once
// Tiled deferred lighting in compute (one workgroup per tile: depth bounds, light culling
// into shared memory, shading of the tile's pixels; per sample on MSAA edges only). Also
// writes per-tile statistics and, for blended scenes, the transparent light lists.
#include "core/gpu/frame_graph.h"
#include "deferred/deferred_targets.h"
#include "core/gpu/descriptors.h"

namespace tp {

class GpuContext;
class SceneGpu;

class TiledLighting {
  public:
    TiledLighting(GpuContext& ctx, SceneGpu& scene, bool debug) : ctx_(ctx), scene_(scene), debug_(debug) {}
    ~TiledLighting();
    // listsOnly: volumes lighting shades the opaque surfaces; only the transparent lists
    // (and the tile statistics) are built here.
    void plan(FrameGraph& graph, DeferredTargets& t, bool listsOnly = false);
    void prepare(FrameGraph& graph);

  private:
    void record(PassContext& pc);
    std::string shaderName() const;
    GpuContext& ctx_;
    SceneGpu& scene_;
    bool debug_;
    bool listsOnly_ = false;
    const DeferredTargets* t_ = nullptr;
    PassSet set_;
    VkSampler sampler_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

} // namespace tp
