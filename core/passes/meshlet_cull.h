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
// docs/geometry.md.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/resources.h"
#include "core/renderer/cull_geometry_knob.h"

namespace tp {
class GpuContext;
class SceneGpu;
struct DrawItem;
} // namespace tp

namespace tp::passes {

class MeshletCull {
  public:
    // draws: the draws it culls (each gets a slot; a geometry pass may record only these).
    // firstTriangle: each command's firstInstance is its meshlet's first triangle in the
    // meshlet index buffer (TP_MC_FLAG_FIRST_TRIANGLE; the visibility pass's ids), else 0.
    // Builds the scene's meshlets if nobody has (SceneGpu::buildMeshlets). Throws
    // RendererError where the device lacks drawIndirectCount or multiDrawIndirect (and, with
    // firstTriangle, drawIndirectFirstInstance).
    MeshletCull(GpuContext& ctx, SceneGpu& scene, std::vector<const DrawItem*> draws,
                bool firstTriangle = false);
    ~MeshletCull();
    MeshletCull(const MeshletCull&) = delete;
    MeshletCull& operator=(const MeshletCull&) = delete;

    // Declares the pass and its buffers: meshlet_draws (commands), meshlet_draw_counts,
    // meshlet_cull_stats (exported: read back by collect()).
    void plan(FrameGraph& graph);
    void prepare(FrameGraph& graph);
    // What a pass that records culled draws declares (the commands and their counts).
    std::vector<PassUse> drawUses() const;
    bool holds(const DrawItem& d) const;
    // For a pass that reads the kept meshlets itself (the visibility buffer's compute
    // rasterizer): the commands and counts (read as storage), the slot of a draw given, and the
    // first of that slot's commands (meshletCount of them, the first counts[slot] written).
    ResourceHandle commands() const { return commands_; }
    ResourceHandle counts() const { return counts_; }
    uint32_t slot(const DrawItem& d) const { return slotOf_.at(d.index); }
    uint32_t firstCommand(uint32_t slot) const { return firstCommand_.at(slot); }
    // The culled draw of `d` (one of the draws given): DrawPush (material, pad0), cull mode,
    // vkCmdDrawIndexedIndirectCount. The caller binds the pipeline, the scene set and the
    // meshlet index buffer (SceneGpu::bindMeshletIndexBuffer).
    void recordDraw(PassContext& pc, VkPipelineLayout layout, const DrawItem& d,
                    uint32_t pad0 = 0) const;

    // After a frame: the statistics read back. counters() then names, for the draws culled:
    // meshlets (all of them), meshlets_submitted, meshlets_culled_frustum, meshlets_culled_cone,
    // triangles (all), triangles_submitted.
    void collect(FrameGraph& graph);
    std::vector<std::pair<std::string, double>> counters() const;
    bool collected() const { return collected_; }
    // After collect(): the meshlets kept of one of its draws (the indirect draws recording it
    // issues); 0 before.
    uint32_t kept(const DrawItem& d) const;

  private:
    void record(PassContext& pc);
    GpuContext& ctx_;
    const SceneGpu& scene_;
    std::vector<const DrawItem*> draws_;
    bool firstTriangle_ = false;
    std::vector<uint32_t> slotOf_;       // by DrawItem::index: its slot (~0u: not culled here)
    std::vector<uint32_t> firstCommand_; // by slot
    uint32_t meshlets_ = 0, triangles_ = 0;
    Buffer table_; // CullDraw[] (shaders/passes/meshlet_cull.h)
    ResourceHandle commands_, counts_, stats_;
    PassSet set_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    bool collected_ = false;
    uint64_t submitted_ = 0, frustum_ = 0, cone_ = 0, trianglesSubmitted_ = 0;
    std::vector<uint32_t> keptBySlot_;
};

// What every pipeline's geometry passes cull: the scene's opaque then masked draws, in
// SceneGpu::drawList order (a pass may record a subset: multipass forward's on-screen meshes).
std::vector<const DrawItem*> opaqueAndMaskedDraws(const SceneGpu& scene);

// A pipeline's --cull-geometry for its opaque and masked geometry: with `frustum`, the pass
// over opaqueAndMaskedDraws made in `cull` (firstTriangle as the constructor's) and planned
// into `graph`, returned for the geometry passes; with `none`, nothing and null.
MeshletCull* planOpaqueCull(std::optional<MeshletCull>& cull, GpuContext& ctx, SceneGpu& scene,
                            FrameGraph& graph, CullGeometry mode, bool firstTriangle = false);

} // namespace tp::passes
