#pragma once
// Light binning on the GPU (--light-bin gpu), shared by Forward+ and tiled deferred: the
// runs la::binLights builds on the CPU (light_bins.h), built every frame by three timed
// compute passes, exactly equal (include/light_binning.h says why):
//   light_binning (counts and offsets, 4 dispatches)
//     1. clear   the counts (a difference array)
//     2. rects   per light, its conservative tile rectangle (slab ranges by bisection); its
//                corners in the difference array; in the frame the rectangle, stored for the
//                fill (8 bytes a light)
//     3. rows    a workgroup per row of tiles: prefix sums along it
//     4. columns a workgroup per column: the counts (the bound) and their row-major exclusive
//                prefix sum (the offsets: the compact layout) in one pass down the column
//   light_bin_fill
//     5. fill    per light and covered tile, a slot from the tile's count counted down
//                (atomic: scheduling order); the (light, tile) pairs of each 64 lights
//                spread evenly over the invocations of one or more workgroups (at least
//                TP_BIN_FILL_GROUPS_GPU workgroups on a GPU)
//   light_bin_sort
//     6. sort    every tile's run ascending: a workgroup per tile in shared memory (by rank up
//                to 256, else bitonic); longer runs than shared memory holds by blocks
//                (bitonic steps within a block in shared memory, across blocks a dispatch each)
// The buffers need their sizes before the frame, so the pipeline calls sizes() at plan time:
// steps 1-4 once, then readbacks of the counts and the offsets: the numbers the CPU path
// gives. A renderer that follows a new view (Renderer::updateView) calls sizes() again for it:
// the slab planes follow the projection, the sort follows the new longest run, and the frame's
// buffers are bound again afterwards.
#include <cstdint>
#include <string>
#include <vector>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/resources.h"
#include "core/lightassign/light_bins.h"
#include "core/lightassign/tile_grid.h"

namespace tp {
class GpuContext;
class SceneGpu;
} // namespace tp

namespace tp::la {

class GpuBinning {
  public:
    // local: the point/spot light indices, ascending (la::LightClasses::local); owner: the
    // pipeline, for the ledger. The scene's uploaded view and lights are what it bins.
    GpuBinning(GpuContext& ctx, SceneGpu& scene, const TileGrid& grid,
               const std::vector<uint32_t>& local, std::string owner);
    ~GpuBinning();
    GpuBinning(const GpuBinning&) = delete;
    GpuBinning& operator=(const GpuBinning&) = delete;

    // For the scene's current view (plan time, and again per view): steps 1-4 on the GPU, read
    // back. bound, offsets, slots, maxBound; no candidates. Between frames (it waits).
    LightBins sizes();
    // The frame: passes "light_binning" (steps 1-4), "light_bin_fill" (5), "light_bin_sort" (6),
    // timed apart (their own buffers in the graph; exports light_bin_offsets and light_bin_counts).
    void plan(FrameGraph& graph);
    // target: the buffer the culling reads its candidates from (uploaded outside the graph);
    // tile t's run goes to its words [baseWord + offsets[t], baseWord + offsets[t + 1]).
    void prepare(FrameGraph& graph, VkBuffer target, uint64_t baseWord);

  private:
    struct Bufs {
        VkBuffer counts, offsets, rows, rects;
    };
    void destroyPipelines(); // and the layout and pass set
    void bind(const Bufs& b, VkBuffer target);
    void uploadInputs(); // the grid and the slab planes of the current projection
    void recordSizing(VkCommandBuffer cmd, bool storeRects);
    void recordFill(VkCommandBuffer cmd);
    void recordSort(VkCommandBuffer cmd);
    void dispatchFlat(VkCommandBuffer cmd, VkPipeline pipeline, uint32_t count,
                      const gpu::DrawPush& push);
    void dispatchGroups(VkCommandBuffer cmd, VkPipeline pipeline, uint32_t groups,
                        const gpu::DrawPush& push);
    void begin(VkCommandBuffer cmd);

    GpuContext& ctx_;
    SceneGpu& scene_;
    TileGrid grid_;
    uint32_t locals_ = 0;
    std::string owner_;
    uint32_t base_ = 0;     // the target's first word
    uint32_t maxBound_ = 0; // from sizes(): whether long runs need bin_sort_step
    Buffer inputs_, localList_;
    std::vector<uint8_t> inputBytes_; // what inputs_ holds
    Bufs frame_{};                    // prepare(): the frame's buffers, bound again after sizes()
    VkBuffer target_ = VK_NULL_HANDLE;
    ResourceHandle counts_, offsets_, rows_, rects_;
    PassSet set_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    std::vector<VkPipeline> pipelines_; // one per step (kSteps in light_binning.cpp)
};

} // namespace tp::la
