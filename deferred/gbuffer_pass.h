#pragma once
// G-buffer pass: opaque and alpha-masked draws (masked ones discard below the cutoff) write
// the planned layout; blended draws are left to the hybrid forward pass. Under MSAA the
// targets are per sample, and depth is resolved (sample 0) into the exported "depth". With a
// MeshletCull (--cull-geometry frustum or full) the opaque and masked draws are the meshlets it
// kept, with the same shaders: a culled meshlet has no fragment in front of what the G-buffer
// keeps. With occlusion (full) the pass is "gbuffer" (last frame's visible meshlets), the
// depth pyramid and the late cull, then "gbuffer_late" (the rest, loading the targets).
// With a depth prepass (--gbuffer-prepass) the pass library's depth_prepass writes the depth
// (culled as above, in its phases) and "gbuffer" tests EQUAL without writing it: one pass over
// every kept meshlet, each sample's material written once instead of once per surface that
// reaches it in draw order (docs/deferred.md, "The depth prepass").
#include <optional>

#include "core/gpu/frame_graph.h"
#include "core/gpu/descriptors.h"
#include "core/passes/depth_prepass.h"
#include "core/passes/materials_ubo.h"
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
    // cull: the meshlets to draw, or null to draw the meshes whole; prepass: depth first.
    void plan(FrameGraph& graph, DeferredTargets& t, passes::MeshletCull* cull = nullptr,
              bool prepass = false);
    // The pass set (the materials' uniform-buffer copy) and the pipelines.
    void prepare(FrameGraph& graph);

  private:
    void record(PassContext& pc, passes::CullPhase phase);
    GpuContext& ctx_;
    SceneGpu& scene_;
    const DeferredTargets* t_ = nullptr;
    passes::MeshletCull* cull_ = nullptr;
    std::optional<passes::DepthPrepass> prepass_;
    std::optional<MaterialsUbo> materialsUbo_; // read on a CPU device (materials_ubo.h)
    PassSet set_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline opaque_ = VK_NULL_HANDLE, masked_ = VK_NULL_HANDLE;
};

} // namespace tp
