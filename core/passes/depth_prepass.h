#pragma once
// The depth prepass, one implementation for every pipeline that has one (Forward+, multipass
// forward): depth only for opaque draws, the alpha test of every other pass for masked ones
// (prepass_mask.frag), blended draws left out. After it every shading pass tests EQUAL, so
// each sample is shaded once per light however deep the scene is.
//
// The masked alpha test runs per sample under MSAA, as the reference's: the same interpolants
// per sample, so the same coverage. The rate is stated in the pipeline (sample shading), not
// only implied by prepass_mask.frag's `sample` inputs (which force it on their own: the two
// copies this replaces, Forward+'s without the flag and multipass's with it, drew the same).
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/frame_graph.h"

namespace tp {
class GpuContext;
class SceneGpu;
struct DrawItem;
} // namespace tp

namespace tp::passes {

class MeshletCull;
enum class CullPhase;

struct DepthPrepassParams {
    uint32_t samples = 1;
    std::vector<const DrawItem*> opaque, masked; // the draws it records, in this order
    // Pipelines for every alpha mode the scene has, not only for the non-empty lists: a
    // renderer that follows many views (RenderSettings::manyViews) gets new lists per view.
    bool everyPipeline = false;
    VkFormat depthFormat = VK_FORMAT_D32_SFLOAT; // the depth target's (and resolve's) format
    // --cull-geometry: the draws are recorded as the meshlets this pass kept (every draw of
    // the lists must be among its draws); null: each draw whole, from the scene's indices.
    // With occlusion (full) the prepass is two passes around the depth pyramid and the late
    // cull: depth_prepass (last frame's visible meshlets) and depth_prepass_late (the rest).
    MeshletCull* cull = nullptr;
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
    // Declares pass "depth_prepass": writes `t.depth`, resolves into `t.resolve` (with
    // occlusion culling also "depth_prepass_late", after the pyramid: planGeometryPass).
    void plan(FrameGraph& graph, DepthPrepassTargets t);
    // Pipelines (after the graph is compiled; they depend on no resource).
    void prepare();
    uint32_t draws() const { return draws_; } // recorded in the last frame
    uint32_t lateDraws() const { return lateDraws_; } // by depth_prepass_late (occlusion culling)
    // A new view's lists (recorded from the next recording on); false, and nothing changed,
    // when a non-empty list has no pipeline (it was empty at prepare, without everyPipeline).
    bool setDraws(std::vector<const DrawItem*> opaque, std::vector<const DrawItem*> masked);

  private:
    void record(PassContext& pc, CullPhase phase);
    GpuContext& ctx_;
    const SceneGpu& scene_;
    DepthPrepassParams params_;
    DepthPrepassTargets t_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline opaque_ = VK_NULL_HANDLE, masked_ = VK_NULL_HANDLE;
    uint32_t draws_ = 0, lateDraws_ = 0;
};

} // namespace tp::passes
