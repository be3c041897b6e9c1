#pragma once
// G-buffer pass: opaque and alpha-masked draws (masked ones discard below the cutoff) write
// the planned layout; blended draws are left to the hybrid forward pass. Under MSAA the
// targets are per sample, and depth is resolved (sample 0) into the exported "depth". With a
// MeshletCull (--cull-geometry frustum) the opaque and masked draws are the meshlets it kept,
// with the same shaders: a culled meshlet has no fragment in front of what the G-buffer keeps.
#include "core/gpu/frame_graph.h"
#include "deferred/deferred_targets.h"

namespace tp {

class GpuContext;
class SceneGpu;
namespace passes {
class MeshletCull;
}

class GBufferPass {
  public:
    GBufferPass(GpuContext& ctx, SceneGpu& scene) : ctx_(ctx), scene_(scene) {}
    ~GBufferPass();
    // cull: the meshlets to draw, or null to draw the meshes whole.
    void plan(FrameGraph& graph, DeferredTargets& t, const passes::MeshletCull* cull = nullptr);
    void prepare();

  private:
    void record(PassContext& pc);
    GpuContext& ctx_;
    SceneGpu& scene_;
    const DeferredTargets* t_ = nullptr;
    const passes::MeshletCull* cull_ = nullptr;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline opaque_ = VK_NULL_HANDLE, masked_ = VK_NULL_HANDLE;
};

} // namespace tp
