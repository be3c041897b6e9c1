#pragma once
// G-buffer pass: opaque and alpha-masked draws (masked ones discard below the cutoff) write
// the planned layout; blended draws are left to the hybrid forward pass. Under MSAA the
// targets are per sample, and depth is resolved (sample 0) into the exported "depth". With a
// MeshletCull (--cull-geometry frustum or full) the opaque and masked draws are the meshlets it
// kept, with the same shaders: a culled meshlet has no fragment in front of what the G-buffer
// keeps. With occlusion (full) the pass is "gbuffer" (last frame's visible meshlets), the
// depth pyramid and the late cull, then "gbuffer_late" (the rest, loading the targets).
#include "core/gpu/frame_graph.h"
#include "deferred/deferred_targets.h"

namespace tp {

class GpuContext;
class SceneGpu;
namespace passes {
class MeshletCull;
enum class CullPhase;
} // namespace passes

class GBufferPass {
  public:
    GBufferPass(GpuContext& ctx, SceneGpu& scene) : ctx_(ctx), scene_(scene) {}
    ~GBufferPass();
    // cull: the meshlets to draw, or null to draw the meshes whole.
    void plan(FrameGraph& graph, DeferredTargets& t, passes::MeshletCull* cull = nullptr);
    void prepare();

  private:
    void record(PassContext& pc, passes::CullPhase phase);
    GpuContext& ctx_;
    SceneGpu& scene_;
    const DeferredTargets* t_ = nullptr;
    const passes::MeshletCull* cull_ = nullptr;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline opaque_ = VK_NULL_HANDLE, masked_ = VK_NULL_HANDLE;
};

} // namespace tp
