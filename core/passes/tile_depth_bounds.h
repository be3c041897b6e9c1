#pragma once
// The tile depth bounds pass (pass "tile_depth_bounds", compute;
// shaders/passes/tile_depth_bounds.comp): one workgroup per tile reduces every depth sample of
// its pixels to the tile's nearest and farthest geometry depth and whether it sees the sky,
// into a buffer of one uvec4 per tile (passes/tiled_lighting.h: TP_TL_BINDING_TILE_DEPTH),
// which the tiled lighting pass culls against. The tiled lighting made this reduction inline
// until it was measured to cost its whole kernel more under MSAA than a pass of its own
// (docs/deferred.md, "Tile depth bounds").
#include <vulkan/vulkan.h>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/lightassign/tile_grid.h"

namespace tp {
class GpuContext;
class SceneGpu;

class TileDepthBounds {
  public:
    TileDepthBounds(GpuContext& ctx, SceneGpu& scene) : ctx_(ctx), scene_(scene) {}
    ~TileDepthBounds();
    TileDepthBounds(const TileDepthBounds&) = delete;
    TileDepthBounds& operator=(const TileDepthBounds&) = delete;

    // Declares the pass over `depth` (per-sample D32, `samples` of them) and returns the
    // bounds buffer it writes.
    ResourceHandle plan(FrameGraph& graph, ResourceHandle depth, uint32_t samples,
                        const la::TileGrid& grid);
    void prepare(FrameGraph& graph);

  private:
    void record(PassContext& pc);
    GpuContext& ctx_;
    SceneGpu& scene_;
    la::TileGrid grid_;
    uint32_t samples_ = 1;
    PassSet set_;
    VkSampler sampler_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

} // namespace tp
