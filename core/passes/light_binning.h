#pragma once
// Light binning on the GPU (--light-bin gpu), shared by Forward+ and tiled deferred: the
// runs la::binLights builds on the CPU (light_bins.h), built every frame by three timed
// compute passes, exactly equal (include/light_binning.h says why):
//   light_binning (counts and offsets, 4 dispatches; a 5th for a word layout, publishWords:
//                the transparent lists' masks, clustered Forward+'s slice rows)
//     1. clear   the counts (a difference array) and the direct counts
//     2. rects   per light, its conservative tile rectangle (slab ranges by bisection); its
//                corners in the difference array, or a rectangle of fewer tiles than corners
//                each tile in the direct counts (folded in by step 3); in the frame the
//                rectangle, stored for the fill (8 bytes a light)
//     3. rows    a workgroup per row of tiles: prefix sums along it, the direct counts
//                folded in
//     4. columns a workgroup per column: the counts (the bound) and their row-major exclusive
//                prefix sum (the offsets: the compact layout) in one pass down the column
//   light_bin_fill
//     5. fill    per light and covered tile, a slot from the tile's count counted down
//                (atomic: scheduling order); the (light, tile) pairs of each 64 lights
//                spread evenly over the invocations of one or more workgroups (at least
//                TP_BIN_FILL_GROUPS_GPU workgroups on a GPU, each 64 lights' pairs over
//                at most TP_BIN_FILL_SPLIT_MAX workgroups)
//   light_bin_sort
//     6. sort    every tile's run ascending: a workgroup per tile in shared memory (by rank up
//                to 128 lights, else by buckets over the lights' index range, bitonic where a
//                bucket is crowded); longer runs than shared memory holds by blocks (bitonic
//                steps within a block in shared memory, across blocks a dispatch each)
// The buffers need their sizes before the frame, so the pipeline calls sizes() at plan time:
// steps 1-4 once, then readbacks of the counts and the offsets: the numbers the CPU path
// gives. A renderer that follows a new view (Renderer::updateView) needs no readback: the
// frame's step 4 also publishes the offsets into the consumer's buffer (prepare's
// offsetsWord), each clamped to the planned room, so the culling and shading read the GPU's
// layout of that view; the fill and the sort stay inside the clamped runs. What the view
// needed (the total and the longest run) is left after the offsets for overflowed(), read
// after the view's frames: a view past the room or past the planned longest run is counted
// there and the renderer is planned again (the contract's step 7), never shown cut.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/resources.h"
#include "core/lightassign/light_bins.h"
#include "core/lightassign/tile_grid.h"
#include "core/renderer/renderer.h"

namespace tp {
class GpuContext;
class SceneGpu;
} // namespace tp

namespace tp::la {

// Many views: the longest run planned, over the first view's (core/passes/light_binning.h).
constexpr uint32_t kRunHeadroom = 2;
// bin_sort.comp's buckets (TP_BIN_SORT_BUCKETS).
constexpr uint32_t kSortBuckets = 256;
// The longest run bin_sort.comp sorts in shared memory (TP_BIN_SHARED_SORT).
constexpr uint32_t kSharedSortWords = 4096;

// Choices the callers leave to the pass; tests force them.
struct BinningTuning {
    // The short runs' sort buckets (bin_sort.comp), a power of two; tests give few, to crowd them.
    uint32_t sortBuckets = kSortBuckets;
    // The fill's reserved shared memory (include/light_binning.h: TP_BIN_FILL_RESERVE_WORDS);
    // unset: on a GPU with at least TP_BIN_FILL_RESERVE_PER_TILE point/spot lights per tile of
    // the grid (their number over the tiles', not how many cover a tile).
    std::optional<bool> fillReserve;
};

class GpuBinning {
  public:
    // local: the point/spot light indices, ascending (la::LightClasses::local); owner: the
    // pipeline, for the ledger. The scene's uploaded view and lights are what it bins.
    // manyViews: the longest run the frame plans for (runBound) gets kRunHeadroom over the
    // first view's.
    GpuBinning(GpuContext& ctx, SceneGpu& scene, const TileGrid& grid,
               const std::vector<uint32_t>& local, std::string owner, bool manyViews = false,
               const BinningTuning& tuning = {});
    ~GpuBinning();
    GpuBinning(const GpuBinning&) = delete;
    GpuBinning& operator=(const GpuBinning&) = delete;

    // For the scene's current view (plan time): steps 1-4 on the GPU, read back. bound,
    // offsets, slots, maxBound; no candidates. Between frames (it waits). The first call also
    // plans runBound().
    LightBins sizes();
    // A new view followed without sizes(): the slab planes again where the projection moved
    // (an upload only then). The frame bins the view itself.
    void followView() { uploadInputs(); }
    // The point and spot lights it bins.
    uint32_t locals() const { return locals_; }
    // The longest run the frame is recorded for (the sort's steps, the consumers' batches):
    // the first sizes()'s maxBound, with kRunHeadroom under many views, at most every local
    // light. A longer run is an overflow (overflowed()).
    uint32_t runBound() const { return runBound_; }
    // Plan-time sizing runs so far (a readback each): 1 per plan when views follow on the GPU.
    uint32_t sizingRuns() const { return sizingRuns_; }
    // The frame: passes "light_binning" (steps 1-4), "light_bin_fill" (5), "light_bin_sort" (6),
    // timed apart (their own buffers in the graph; exports light_bin_offsets and light_bin_counts).
    void plan(FrameGraph& graph);
    // target: the buffer the culling reads its candidates from (uploaded outside the graph);
    // tile t's run goes to its words [baseWord + offsets[t], baseWord + offsets[t + 1]), and
    // the frame writes offsets[0..tiles] to its words from offsetsWord, each clamped to `room`
    // (the run slots the target holds from baseWord).
    void prepare(FrameGraph& graph, VkBuffer target, uint64_t baseWord, uint64_t offsetsWord,
                 uint64_t room);
    // The frame also lays out, into `out` (tiles + 1 words from its word `firstWord`),
    // scale * ceil((add + count) / 32) words per tile (a bit per candidate: the transparent
    // lists' masks, scale 1; clustered Forward+'s slice rows, scale = slices), clamped to
    // `room`; a view needing more is an overflow too. After prepare. `out` may be the target.
    // indices: a word per candidate instead of a bit, scale * (add + count) words a tile (the
    // transparent lists as light indices).
    void publishWords(VkBuffer out, uint32_t scale, uint32_t add, uint64_t room,
                      uint64_t firstWord = 0, bool indices = false);
    // After a view's frames: whether the view needed more than the plan holds: more slots than
    // the room, more words than publishWords's room, or a run longer than runBound() where that
    // changes what was recorded (the sort's steps, or the consumer's batches of `batch` lights
    // over `extra` + the run: ceil((extra + run) / batch)). Its lists were then cut, and the
    // caller plans again. Reads the view's needs back (a few words).
    bool overflowed(FrameGraph& graph, uint32_t batch, uint32_t extra = 0);
    // After a frame: its layout (bound, offsets, slots, maxBound) read back, for statistics.
    LightBins collect(FrameGraph& graph);
    // The last collected frame's atomics on the counts (bin_rects.comp: a rectangle's corners in
    // the difference array, or a small one's tiles in the direct counts; la::binCornerAtomics).
    uint64_t cornerAtomics() const { return cornerAtomics_; }
    // The longest run the short-run sort holds in shared memory: runBound() rounded up to a
    // power of two, 256 to 4,096 (kSharedSortWords), from the first sizes().
    uint32_t sortSharedRun() const { return sharedRun_; }
    // Whether the fill's workgroup reserves shared memory (BinningTuning::fillReserve).
    bool fillReserved() const { return fillReserve_; }
    // Its runs the sort gave the bitonic network because a bucket was crowded (a statistic).
    uint32_t sortFallbacks() const { return sortFallbacks_; }
    // The counters light_bin_sizing_runs (plan-time readbacks: views followed add none) and
    // light_bin_sort_fallbacks, and the passes' counted work (addBinningWork) for the last
    // collected frame, which binned into `slots` (light, tile) pairs.
    void addStats(RendererStats& s, uint64_t slots) const;

  private:
    struct Bufs {
        VkBuffer counts, offsets, rows, rects;
    };
    void destroyPipelines(); // and the layout and pass set
    uint64_t countCornerAtomics(const std::vector<uint8_t>& rectBytes) const;
    void bind(const Bufs& b, VkBuffer target);
    void uploadInputs(); // the grid and the slab planes of the current projection
    void sizeSortRun();  // the sort's shared run for runBound_ (its pipeline again)
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
    uint64_t cornerAtomics_ = 0;
    uint32_t sortFallbacks_ = 0;
    std::string owner_;
    uint32_t base_ = 0;     // the target's first word
    uint32_t offsetsWord_ = 0, room_ = 0; // prepare(): where the frame publishes its offsets
    uint32_t runBound_ = 0; // from the first sizes(): whether long runs need bin_sort_step
    uint32_t sizingRuns_ = 0;
    bool manyViews_ = false;
    bool fillReserve_ = false;
    uint32_t sharedRun_ = kSharedSortWords; // bin_sort.comp's run in shared memory
    std::vector<SpecConstant> spec_;        // the pipelines' specialization
    Buffer inputs_, localList_;
    std::vector<uint8_t> inputBytes_; // what inputs_ holds
    Bufs frame_{};                    // prepare(): the frame's buffers, bound again after sizes()
    struct Words {
        VkBuffer buffer = VK_NULL_HANDLE;
        uint32_t scale = 0, add = 0, room = 0, first = 0;
    } words_; // publishWords()
    VkBuffer target_ = VK_NULL_HANDLE;
    ResourceHandle counts_, offsets_, rows_, rects_;
    PassSet set_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    std::vector<VkPipeline> pipelines_; // one per step (kSteps in light_binning.cpp)
};

// The binning passes' counted work (docs/efficiency.md, "Placing a pass: what is counted") for
// a frame that binned `locals` lights into `slots` (light, tile) pairs: light_binning reads each
// light's index, position and range; light_bin_fill makes one returning atomicAdd per pair (its slot in the tile's run)
// and writes the pair's light index; light_bin_sort reads and writes every run once (at least:
// a run longer than shared memory is passed over a step at a time); light_binning's
// `corners` atomics on the counts (GpuBinning::cornerAtomics). The runs and the
// lights live outside the frame graph, so their bytes are added here. The sort's compares
// are not counted: no ceiling measures them.
void addBinningWork(RendererStats& s, uint64_t slots, uint32_t locals, uint64_t corners);

} // namespace tp::la
