#pragma once
// The visibility pass (pass "visibility"): opaque and alpha-masked draws write depth and the
// packed (draw, triangle) id of the visible surface per sample (visbuffer/vis_shared.h), and
// nothing else: 4 bytes of id per sample beside depth. Masked draws alpha-test per sample
// under MSAA, as the depth prepass does. Under MSAA the depth is resolved (sample 0) into the
// exported "depth"; blended draws are left to the hybrid forward pass. The ids are zeroed
// before it by compute ("visibility_ids_clear", core/passes/image_clear.h) where the device can
// store to them; the pass then clears the depth only. Drawing every draw itself (the hardware
// rasterization, one phase or occlusion's two) with no debug image to show them, it does not
// clear the ids at all: a sample it leaves unwritten keeps its depth's clear value, which the
// resolve reads first (vis_read.glsl: fetchId, TP_VIS_SPEC_IDS_BY_DEPTH).
//
// With a MeshletCull (--cull-geometry frustum) it draws the meshlets that pass kept, each
// command's firstInstance its meshlet's first triangle: the shaders' meshlet variants map
// gl_PrimitiveID back to the draw's triangle (SceneGpu::meshletSourceTriangleBuffer, bound in
// its set 1), so every id is the one the whole draw writes (docs/geometry.md). With occlusion
// (--cull-geometry full) it is "visibility" (last frame's visible meshlets), the depth pyramid
// and the late cull, then "visibility_late" (the rest, loading the ids and the depth).
//
// With the compute rasterizer (--vis-raster compute|hybrid, raster_pass.h) it makes the same
// targets, but draws only what the hardware keeps: nothing in compute mode (no pass is added),
// the masked draws in hybrid mode, and leaves the MSAA depth resolve to the merge after it
// (raster_merge_pass.h).
#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/passes/image_clear.h"
#include "visbuffer/draw_table.h"

namespace tp {

class GpuContext;
class SceneGpu;
namespace passes {
class MeshletCull;
enum class CullPhase;
} // namespace passes

namespace vis {

struct VisibilityTargets {
    ResourceHandle ids;   // R32_SFLOAT per sample (the id's exact integer value)
    ResourceHandle depth; // D32 per sample (the resolved depth itself at 1x)
};

class VisibilityPass {
  public:
    VisibilityPass(GpuContext& ctx, SceneGpu& scene, const DrawTable& table)
        : ctx_(ctx), scene_(scene), table_(table), idsClear_(ctx) {}
    ~VisibilityPass();
    // The id and depth targets; resolvedDepth: the single-sample "depth" output (the depth
    // target itself at 1x).
    VisibilityTargets createTargets(FrameGraph& graph, uint32_t samples,
                                    ResourceHandle resolvedDepth);
    // The pass drawing into `targets`. cull: the meshlets to draw (made with firstTriangle), or
    // null to draw the meshes whole. draws: what --vis-raster leaves to the hardware (Hardware:
    // everything). seeded: the compute rasterizer wrote the targets already (1x), so the pass
    // keeps them instead of clearing.
    enum class Draws { All, Masked, None };
    // keepIds: every sample's id is read as it is (the debug images), so the ids are cleared.
    void plan(FrameGraph& graph, const VisibilityTargets& targets,
              passes::MeshletCull* cull = nullptr, Draws draws = Draws::All, bool seeded = false,
              bool keepIds = false);
    void prepare(FrameGraph& graph);
    // The ids are not cleared: a reader takes a sample's id only where its depth holds geometry.
    bool idsByDepth() const { return idsByDepth_; }

  private:
    void record(PassContext& pc, passes::CullPhase phase);
    GpuContext& ctx_;
    SceneGpu& scene_;
    const DrawTable& table_;
    uint32_t samples_ = 1;
    VisibilityTargets t_;
    ResourceHandle resolved_;
    const passes::MeshletCull* cull_ = nullptr;
    Draws draws_ = Draws::All;
    bool seeded_ = false;
    bool idsByDepth_ = false;
    PassSet set_; // culled: the source triangles
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline opaque_ = VK_NULL_HANDLE, masked_ = VK_NULL_HANDLE;
    // visibility_ids_clear: the ids zeroed by compute, not by the pass's clear (a render
    // pass's clear runs on the graphics SMs: on the H200 0.59 ms for the ids at 1080p 4x),
    // where they are cleared at all (not idsByDepth_).
    ImageClear idsClear_;
};

} // namespace vis
} // namespace tp
