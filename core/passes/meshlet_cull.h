#pragma once
// Meshlet culling on the GPU (pass "meshlet_cull", compute; shaders/passes/meshlet_cull.comp):
// for each of the draws it is given, every meshlet of the draw's mesh (SceneGpu, built with
// meshoptimizer the first time a pass culls) is tested against the view frustum (bounding
// sphere against the six planes) and, where the draw's material is single-sided, against its
// normal cone (the whole cluster faces away from the eye); the kept meshlets become indirect
// draw commands of the draw's range, in meshlet order, with their count. A geometry pass then
// records each of those draws as one vkCmdDrawIndexedIndirectCount over the scene's meshlet
// index buffer, with the draw's push constants and cull mode as before: its shaders do not
// change.
//
// It culls only what cannot produce a fragment: a sphere wholly outside a clip plane, a
// cluster whose every triangle the rasterizer's back-face culling would drop (with margins
// for rounding, include/meshlets.h). A double-sided material is never cone-culled. Mirrored
// nodes need nothing: the loader flipped their winding, so the cones follow the front faces.
//
// With occlusion (--cull-geometry full) it culls in two phases, as niagara does. The early
// phase ("meshlet_cull") keeps, of what passes the frustum and the cone, the meshlets visible
// at the end of the last frame (a word per meshlet kept across frames; the first frame treats
// every meshlet as visible); the geometry pass that writes depth draws them; "depth_pyramid"
// reduces that depth; the late phase ("meshlet_cull_late") tests every meshlet again, then
// its sphere's screen rectangle and nearest depth against the pyramid, writes each one's
// visibility for the next frame and keeps the visible ones the early phase did not draw; the
// geometry pass draws those too (its second pass, "<name>_late", loading what the first
// wrote). A pass after both draws both phases' meshlets. A meshlet is dropped only when its
// sphere lies wholly behind the farthest depth already written where it would project
// (margins in include/meshlets.h), so what it would have drawn fails the depth test anyway.
// docs/geometry.md, "Occlusion".
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/resources.h"
#include "core/gpuscene/scene_gpu.h" // DrawItem: slot() reads it inline
#include "core/renderer/cull_geometry_knob.h"

namespace tp {
class GpuContext;
class SceneGpu;
struct DrawItem;
} // namespace tp

namespace tp::passes {

class DepthPyramid;

// Which of the culled meshlets a geometry pass draws: with occlusion, the early phase's (the
// pass that writes depth, before the pyramid), the late phase's (its second pass), or both
// (every pass after them). Without occlusion there is one phase: Early and Both draw it, Late
// draws nothing.
enum class CullPhase { Early, Late, Both };

class MeshletCull {
  public:
    // draws: the draws it culls (each gets a slot; a geometry pass may record only these).
    // firstTriangle: each command's firstInstance is its meshlet's first triangle in the
    // meshlet index buffer (TP_MC_FLAG_FIRST_TRIANGLE; the visibility pass's ids), else 0.
    // occlusion: --cull-geometry full (two phases; the geometry pass that writes depth plans
    // them with planGeometryPass).
    // Builds the scene's meshlets if nobody has (SceneGpu::buildMeshlets). Throws
    // RendererError where the device lacks drawIndirectCount or multiDrawIndirect (and, with
    // firstTriangle, drawIndirectFirstInstance).
    MeshletCull(GpuContext& ctx, SceneGpu& scene, std::vector<const DrawItem*> draws,
                bool firstTriangle = false, bool occlusion = false);
    ~MeshletCull();
    MeshletCull(const MeshletCull&) = delete;
    MeshletCull& operator=(const MeshletCull&) = delete;

    // Declares the (early) pass and its buffers: meshlet_draws (commands),
    // meshlet_draw_counts, meshlet_cull_stats (exported: read back by collect()).
    void plan(FrameGraph& graph);
    // With occlusion, after the pass that draws the early phase's meshlets: the depth pyramid
    // from `depth` (what that pass wrote) and the late phase, with its buffers
    // (meshlet_draws_late, meshlet_draw_counts_late, meshlet_cull_stats_late).
    void planLate(FrameGraph& graph, ResourceHandle depth);
    void prepare(FrameGraph& graph);
    bool occlusion() const { return occlusion_; }
    // What a pass that records culled draws of `phase` declares (the commands and their counts).
    std::vector<PassUse> drawUses(CullPhase phase = CullPhase::Both) const;
    bool holds(const DrawItem& d) const;
    // For a pass that reads the kept meshlets itself (the visibility buffer's compute
    // rasterizer; the early phase's only, so it refuses occlusion): the commands and counts (read as storage), the slot of a draw given, and the
    // first of that slot's commands (meshletCount of them, the first counts[slot] written).
    ResourceHandle commands() const { return early_.commands; }
    ResourceHandle counts() const { return early_.counts; }
    uint32_t slot(const DrawItem& d) const { return slotOf_.at(d.index); }
    uint32_t firstCommand(uint32_t slot) const { return firstCommand_.at(slot); }
    // The culled draw of `d` (one of the draws given) in `phase`: DrawPush (material, pad0),
    // cull mode, one vkCmdDrawIndexedIndirectCount per phase. The caller binds the pipeline,
    // the scene set and the meshlet index buffer (SceneGpu::bindMeshletIndexBuffer).
    void recordDraw(PassContext& pc, VkPipelineLayout layout, const DrawItem& d,
                    uint32_t pad0 = 0, CullPhase phase = CullPhase::Both) const;

    // After a frame: the statistics read back. counters() then names, for the draws culled:
    // meshlets (all of them), meshlets_submitted, meshlets_culled_frustum, meshlets_culled_cone,
    // triangles (all), triangles_submitted; with occlusion also meshlets_culled_occlusion and
    // each phase's meshlets_submitted_early/_late and triangles_submitted_early/_late.
    void collect(FrameGraph& graph);
    std::vector<std::pair<std::string, double>> counters() const;
    bool collected() const { return collected_; }
    // After collect(): the meshlets kept of one of its draws (the indirect draws recording it
    // issues); 0 before.
    uint32_t kept(const DrawItem& d) const;

  private:
    struct Phase; // one phase's buffers, descriptor set and pipeline
    void record(PassContext& pc, Phase& p);
    void preparePhase(FrameGraph& graph, Phase& p, const std::string& pass,
                      const std::string& shader);
    GpuContext& ctx_;
    const SceneGpu& scene_;
    std::vector<const DrawItem*> draws_;
    bool firstTriangle_ = false;
    bool occlusion_ = false;
    std::vector<uint32_t> slotOf_;       // by DrawItem::index: its slot (~0u: not culled here)
    std::vector<uint32_t> firstCommand_; // by slot
    uint32_t meshlets_ = 0, triangles_ = 0;
    Buffer table_;   // CullDraw[] (shaders/passes/meshlet_cull.h)
    Buffer history_; // with occlusion: a word per meshlet, kept across frames (TP_MC_HISTORY_*)
    struct Phase {
        ResourceHandle commands, counts, stats;
        PassSet set;
        VkPipelineLayout layout = VK_NULL_HANDLE;
        VkPipeline pipeline = VK_NULL_HANDLE;
        bool planned = false;
    };
    Phase early_, late_;
    std::unique_ptr<DepthPyramid> pyramid_;
    ResourceHandle pyramidBuffer_;
    bool collected_ = false;
    struct Totals {
        uint64_t submitted = 0, frustum = 0, cone = 0, occlusion = 0, triangles = 0;
    };
    Totals earlyTotals_, lateTotals_;
    std::vector<uint32_t> keptBySlot_;
};

// A geometry pass that writes the depth occlusion is tested against (the depth prepass,
// deferred's G-buffer, the visibility pass): without occlusion (no cull, or frustum) one pass
// `name` that records CullPhase::Both; with it, `name` (CullPhase::Early), the pyramid and the
// late phase from `depth`, then `name` + "_late" (CullPhase::Late: it must load the targets
// the first wrote). Both declare `uses` and the phase's draw uses.
void planGeometryPass(FrameGraph& graph, MeshletCull* cull, const std::string& name,
                      std::vector<PassUse> uses, ResourceHandle depth,
                      std::function<void(PassContext&, CullPhase)> record);

// What every pipeline's geometry passes cull: the scene's opaque then masked draws, in
// SceneGpu::drawList order (a pass may record a subset: multipass forward's on-screen meshes).
std::vector<const DrawItem*> opaqueAndMaskedDraws(const SceneGpu& scene);

// A pipeline's --cull-geometry for its opaque and masked geometry: with `frustum` or `full`,
// the pass over opaqueAndMaskedDraws made in `cull` (firstTriangle as the constructor's, with
// occlusion for `full`) and planned into `graph`, returned for the geometry passes; with
// `none`, nothing and null.
MeshletCull* planOpaqueCull(std::optional<MeshletCull>& cull, GpuContext& ctx, SceneGpu& scene,
                            FrameGraph& graph, CullGeometry mode, bool firstTriangle = false);

} // namespace tp::passes
