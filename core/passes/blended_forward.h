#pragma once
// The hybrid forward pass (pass "transparent_forward"): blended draws, back to front,
// alpha-blended into hdr (into every covered sample of hdr_msaa, then resolved, under MSAA),
// lit from the per-tile transparent light lists that tiled lighting writes
// (tiled_lighting.h, blended_lists.h); shaded once per pixel or per sample as `perPixel`
// says. A pipeline that shades opaque surfaces from a surface source (deferred, a
// visibility buffer) composes it for what that source cannot hold.
#include <optional>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/resources.h"
#include "core/lightassign/tile_grid.h"
#include "core/passes/lights_ubo.h"
#include "core/passes/material_pipelines.h"
#include "core/passes/materials_ubo.h"

namespace tp {

class GpuContext;
class SceneGpu;
class ShadowMaps;

// hdrMsaa valid under MSAA only; depth: the per-sample depth of the opaque surfaces (tested,
// not written); lists: the transparent lists; bounds: the blended depth bounds; shadows: the
// shadow atlas the blended fragments sample when it is enabled (Atlas residency; null or not
// enabled: no shadows, the pass as it was before them). Blended surfaces receive shadows;
// they cast none (the maps hold opaque and masked draws).
struct BlendedForwardTargets {
    la::TileGrid grid;
    uint32_t samples = 1;
    bool perPixel = false; // under MSAA: once per pixel at the centre (--msaa-shading pixel)
    ResourceHandle hdr, hdrMsaa, depth, lists, bounds;
    VkFormat hdrFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    const ShadowMaps* shadows = nullptr;
    bool msaa() const { return samples > 1; }
};

class BlendedForwardPass {
  public:
    BlendedForwardPass(GpuContext& ctx, SceneGpu& scene)
        : ctx_(ctx), scene_(scene), pipelines_(ctx) {}
    ~BlendedForwardPass();
    // slices > 0 with `masks` (--light-assign clustered): fragments take their cluster's
    // lights through the slice rows the tiled pass wrote over the transparent lists.
    // blendBounds: the blended depth bounds (clustered: where each tile's front slices start).
    void plan(FrameGraph& graph, const BlendedForwardTargets& t, uint32_t slices = 0,
              ResourceHandle masks = {});
    // After the plan: the pass set and the pipeline. The transparent lists are light indices
    // whatever --light-cull says (hybrid_blended.h), so it reads no candidates; binned only
    // says where the ambient term joins the sum (blended_forward.frag: kAmbientLast).
    // lights: the tiled lighting's uniform-buffer copy of the lights (read on a CPU device).
    void prepare(FrameGraph& graph, bool binned, const LightsUbo& lights);

  private:
    void record(PassContext& pc);
    bool shadowed() const;
    GpuContext& ctx_;
    SceneGpu& scene_;
    BlendedForwardTargets t_;
    uint32_t slices_ = 0;
    ResourceHandle masks_;
    Buffer noMasks_; // tiled: a 16-byte stand-in for the unused slice rows
    std::optional<MaterialsUbo> materialsUbo_; // read on a CPU device (materials_ubo.h)
    PassSet set_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    // Each draw's pipeline: its material's texture indices compiled in (material_pipelines.h).
    MaterialPipelines pipelines_;
};

} // namespace tp
