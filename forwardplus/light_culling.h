#pragma once
// Forward+'s light_culling pass (compute; --cull-by invocation: one invocation per tile, 8 x 8
// tiles per workgroup; --cull-by subgroup: one subgroup per tile): depth bounds over every
// sample, point/spot lights against the tile sub-frustum, lists written out in the chosen
// layout; with --light-assign clustered also each depth slice's bitmask. Both ways give the
// same bytes. Split into batches of candidates for lavapipe's loop limit.
#include <cstdint>
#include <string>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/resources.h"
#include "core/lightassign/tile_grid.h"

namespace tp {

class GpuContext;
class SceneGpu;
struct DeviceCaps;

namespace fp {

struct CullConfig {
    la::TileGrid grid;
    uint32_t layout = 0;  // TP_FP_LAYOUT_*
    uint32_t samples = 1; // --msaa
    uint32_t slices = 16; // clustered depth slices
    uint32_t mostTested =
        0; // the most lights any tile tests (binned: its candidates; all: every local light)
    bool binned = true, clustered = false, twoLists = false, blendedSpan = false;
    bool spheres = true; // read the light_spheres pass's buffer (else a stand-in is bound)
    uint32_t subgroupLanes =
        0; // > 0: one subgroup of this many lanes per tile (--cull-by subgroup)
};

// Whether the device can cull a tile with one subgroup (light_culling_subgroup.comp): compute
// subgroups with ballot, arithmetic and vote, full subgroups of its subgroup size on demand,
// and at most 64 lanes. Empty when it can; otherwise the reason.
std::string subgroupCullingUnsupported(const DeviceCaps& caps);

// The resources the pass reads and writes (counter: linked only; masks: clustered only;
// blendBounds: blended scenes only, core/passes/blended_bounds.h; spheres: light_spheres.h;
// centreBounds: --msaa-shading pixel under MSAA only, blended_bounds.h with `opaque`).
struct CullResources {
    ResourceHandle depth, tiles, indices, counter, masks, blendBounds, spheres, centreBounds;
};

class LightCulling {
  public:
    LightCulling(GpuContext& ctx, SceneGpu& scene, const CullConfig& config)
        : ctx_(ctx), scene_(scene), config_(config) {}
    ~LightCulling();
    void plan(FrameGraph& graph, const CullResources& r);
    // params: fp_params, uploaded outside the graph.
    void prepare(FrameGraph& graph, VkBuffer params);
    uint32_t dispatches() const { return dispatches_; } // batches of candidates
    // A new view's most tested lights (binned: its longest candidate run): the batches of the
    // next recording.
    void setMostTested(uint32_t mostTested) { config_.mostTested = mostTested; }
    // Candidates per dispatch (a tile testing more takes several).
    uint32_t batchSize() const;

  private:
    void record(PassContext& pc);

    GpuContext& ctx_;
    SceneGpu& scene_;
    CullConfig config_;
    uint32_t dispatches_ = 0;
    VkSampler sampler_ = VK_NULL_HANDLE;
    Buffer noSpheres_; // without the light_spheres pass: a 16-byte stand-in for its binding
    PassSet set_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    bool blendBounds_ = false;
    Buffer noBlendBounds_; // the shader's bounds binding without blended draws
    bool centreBounds_ = false;
    Buffer noCentreBounds_; // the shader's centre bounds binding where the shading is per sample
};

} // namespace fp
} // namespace tp
