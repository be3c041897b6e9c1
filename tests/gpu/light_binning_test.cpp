// GPU light binning (--light-bin gpu, core/passes/light_binning.h) against the CPU's
// la::binLights: the same bound, offsets and runs, every tile, exactly (the rectangle test
// runs the same float operations on both sides: include/light_binning.h); and every pipeline
// that bins (Forward+, deferred, the visibility buffer) renders byte-identical images either way.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <memory>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "core/gpu/frame_graph.h"
#include "core/gpu/readback.h"
#include "core/gpu/vk_check.h"
#include "core/lightassign/corner_atomics.h"
#include "core/lightassign/light_bins.h"
#include "core/lightassign/light_classes.h"
#include "core/lightassign/tile_bound.h"
#include "core/passes/light_binning.h"
#include "core/scene/lights.h"
#include "core/scene/procedural.h"
#include "forwardplus/light_lists.h"
#include "gpu_test_util.h"
#include "include/light_binning.h"

namespace tp::test {
namespace {

std::vector<Light> pointsAndSpots(const Aabb& bounds, uint32_t count, uint64_t seed,
                                  float rMin = 0.0f, float rMax = 0.0f) {
    LightGenOptions o;
    o.count = count;
    o.seed = seed;
    o.spotWeight = 1.0f; // as many spots as points
    o.radiusMin = rMin;
    o.radiusMax = rMax;
    return generateLights(bounds, o);
}

Scene courtyard(uint32_t lights) {
    Result<Scene> s = makeBuiltinScene("courtyard-small");
    EXPECT_TRUE(s.ok()) << s.error();
    if (!s.ok()) return {};
    Scene scene = std::move(*s);
    scene.lights = pointsAndSpots(scene.bounds, lights, 5);
    return scene;
}

Scene floorWith(uint32_t lights) {
    Scene s = makeFloorScene({});
    Aabb b = s.bounds;
    b.max.y = 3.0f;
    s.lights = pointsAndSpots(b, lights, 11);
    return s;
}

// Lights around the eye: many centres behind it (or beside it, outside the frustum) whose
// spheres still reach in front.
Scene aroundTheEye(uint32_t lights) {
    Scene s = makeFloorScene({});
    const glm::vec3 e = s.camera.position;
    Aabb b{e - glm::vec3(3.0f), e + glm::vec3(3.0f)};
    s.lights = pointsAndSpots(b, lights, 17, 0.5f, 2.5f);
    return s;
}

// Every light covers the whole screen: runs longer than the shared-memory sort takes.
Scene wholeScreen(uint32_t lights) {
    Scene s = makeFloorScene({});
    s.lights = pointsAndSpots(s.bounds, lights, 23, 60.0f, 80.0f);
    return s;
}

// The slab ranges by bisection (lights wholly in front of the eye) are the ranges of a scan
// over every slab: the rectangles, and so the runs, the linear test gave. Lights everywhere
// around a wide frustum, many straddling the eye's plane (those keep the scan).
TEST(GpuLightBinning, BisectedRectanglesEqualEverySlabTested) {
    const la::TileGrid g = la::makeTileGrid(1920, 1080, 16); // 120 x 68 tiles
    const glm::mat4 proj = glm::perspective(glm::radians(70.0f), 1920.0f / 1080.0f, 0.05f, 200.0f);
    const glm::mat4 view =
        glm::lookAt(glm::vec3(1.0f, 2.0f, 3.0f), glm::vec3(0.0f, 1.5f, -4.0f), glm::vec3(0, 1, 0));
    std::mt19937 rng(29);
    std::uniform_real_distribution<float> x(-30.0f, 30.0f), y(-15.0f, 20.0f), z(-40.0f, 15.0f),
        r(0.05f, 6.0f);
    std::vector<gpu::LightGpu> lights(20000);
    for (gpu::LightGpu& l : lights) {
        l.position = {x(rng), y(rng), z(rng)};
        l.range = r(rng);
        l.type = TP_LIGHT_POINT;
    }
    std::vector<uint32_t> local(lights.size());
    for (uint32_t i = 0; i < local.size(); ++i)
        local[i] = i;
    const std::vector<la::TileRect> rects = la::conservativeTileRects(g, view, proj, lights, local);
    const std::vector<glm::vec4> slabs = la::binSlabPlanes(g, proj);
    auto scan = [&](uint32_t loFirst, uint32_t hiFirst, uint32_t count, glm::vec3 c, float rad,
                    int& a, int& b) {
        a = int(count);
        b = -1;
        for (uint32_t i = 0; i < count; ++i)
            if (!gpu::binOutside(slabs[loFirst + i], c, rad) &&
                !gpu::binOutside(slabs[hiFirst + i], c, rad)) {
                a = std::min(a, int(i));
                b = int(i);
            }
    };
    uint32_t inFront = 0, covering = 0, differing = 0;
    for (size_t k = 0; k < lights.size(); ++k) {
        const glm::vec3 c = gpu::binViewCentre(view, lights[k].position);
        const float rad = gpu::binPaddedRadius(lights[k].range, c);
        la::TileRect want;
        if (!gpu::binBehindEye(c, rad)) {
            scan(0, g.tilesX, g.tilesX, c, rad, want.x0, want.x1);
            if (want.x0 <= want.x1)
                scan(2 * g.tilesX, 2 * g.tilesX + g.tilesY, g.tilesY, c, rad, want.y0, want.y1);
        }
        inFront += gpu::binInFront(c, rad) ? 1u : 0u;
        covering += want.empty() ? 0u : 1u;
        const la::TileRect& got = rects[k];
        if (want.empty() != got.empty() ||
            (!want.empty() &&
             (want.x0 != got.x0 || want.x1 != got.x1 || want.y0 != got.y0 || want.y1 != got.y1)))
            ++differing;
    }
    EXPECT_EQ(differing, 0u) << "of " << lights.size();
    EXPECT_GT(inFront, 5000u);  // the bisection ran
    EXPECT_GT(covering, 2000u); // and found rectangles
    EXPECT_LT(inFront, 19000u); // some straddle or lie behind the eye
}

struct Binned {
    la::LightBins cpu;                   // la::binLights, with candidates
    la::LightBins sizes;                 // the GPU's plan-time run
    std::vector<uint32_t> offsets, runs; // the GPU's frame: its offsets, the target's runs
    std::vector<uint32_t> published;     // the offsets the frame wrote into the target
    std::vector<uint32_t> words;         // the word layout it wrote (publishWords)
    uint32_t canary = 0;                 // the target's word past the room
    uint32_t wordCanaries[2] = {};       // the words buffer's words before and after the layout
    bool overflowed = false;             // GpuBinning::overflowed after the frames
    uint32_t largestRect = 0;            // tiles of the largest rectangle, on the CPU
    uint64_t corners = 0, cpuCorners = 0; // atomics on the counts: from the GPU's rectangles, the CPU's
    uint32_t fallbacks = 0;               // runs the sort gave its bitonic network
    bool fillReserved = false;            // the fill's workgroup reserved shared memory
};

constexpr uint32_t kCanary = 0xC0FFEEu;
constexpr uint32_t kWordsAdd = 3; // the word layout's extra candidates per tile (directional)

// The word layout a frame publishes (GpuBinning::publishWords): by default the transparent
// lists' (a bit per candidate and kWordsAdd more a tile) from the buffer's first word.
struct WordLayout {
    uint32_t scale = 1, add = kWordsAdd, first = 0;
    uint64_t room = ~0ull;
};

// One frame of the light_binning pass alone, writing its runs `base` words into a buffer:
// room for `room` slots (all it needs when ~0), then a canary word, then the published
// offsets; `runBound` (when not ~0) the longest run the frame is recorded for. The word
// layout goes to its own buffer, between two canaries.
Binned bin(GpuContext& ctx, SceneGpu& scene, uint32_t w, uint32_t h, uint32_t tile,
           uint32_t frames = 2, uint32_t room = ~0u, bool manyViews = false,
           const WordLayout& layout = {}, const la::BinningTuning& tuning = {}) {
    Binned out;
    scene.setView(w, h, 1);
    const la::TileGrid grid = la::makeTileGrid(w, h, tile);
    const std::vector<uint32_t> local = la::classifyLights(scene.shadingLights()).local;
    const gpu::FrameUniforms& f = scene.shadingFrame();
    out.cpu = la::binLights(grid, f.view, f.proj, scene.shadingLights(), local, true);
    const std::vector<la::TileRect> rects =
        la::conservativeTileRects(grid, f.view, f.proj, scene.shadingLights(), local);
    for (const la::TileRect& r : rects)
        if (!r.empty())
            out.largestRect =
                std::max(out.largestRect, uint32_t(r.x1 - r.x0 + 1) * uint32_t(r.y1 - r.y0 + 1));
    out.cpuCorners = la::binCornerAtomics(rects, grid);
    la::GpuBinning gpuBin(ctx, scene, grid, local, "test", manyViews, tuning);
    out.fillReserved = gpuBin.fillReserved();
    out.sizes = gpuBin.sizes();
    const uint32_t base = 7; // the runs need not start at word 0
    if (room == ~0u) room = uint32_t(out.sizes.slots);
    const uint32_t tiles = grid.count(), offsetsWord = base + room + 1;
    std::vector<uint32_t> init(offsetsWord + tiles + 1, 0);
    init[base + room] = kCanary;
    Buffer target =
        createBufferWithData(ctx, init.data(), init.size() * 4,
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                             {"test", "", "runs", "the runs, a canary, the offsets"});
    const uint32_t wordsFirst = layout.first + 1; // a canary before
    std::vector<uint32_t> wordInit(wordsFirst + tiles + 2, 0);
    wordInit[wordsFirst - 1] = wordInit[wordsFirst + tiles + 1] = kCanary;
    Buffer wordLayout =
        createBufferWithData(ctx, wordInit.data(), wordInit.size() * 4,
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                             {"test", "", "words", "a canary, the word layout, a canary"});
    FrameGraph graph(ctx, "test", w, h);
    gpuBin.plan(graph);
    graph.compile();
    gpuBin.prepare(graph, target.buffer, base, offsetsWord, room);
    gpuBin.publishWords(wordLayout.buffer, layout.scale, layout.add, layout.room, wordsFirst);
    recordAndSubmit(ctx, graph, frames); // a frame rebuilds what the last one left
    out.overflowed = gpuBin.overflowed(graph, 1); // batches of one light: any longer run counts
    gpuBin.collect(graph);
    out.corners = gpuBin.cornerAtomics();
    out.fallbacks = gpuBin.sortFallbacks();
    auto words = [](const std::vector<uint8_t>& bytes, size_t first, size_t n) {
        std::vector<uint32_t> w(n);
        std::memcpy(w.data(), bytes.data() + first * 4, n * 4);
        return w;
    };
    out.offsets = words(readbackBuffer(ctx, graph.buffer(graph.exported("light_bin_offsets"))), 0,
                        grid.count() + 1);
    const std::vector<uint8_t> targetBytes = readbackBuffer(ctx, target);
    out.runs = words(targetBytes, base, std::min<uint64_t>(room, out.sizes.slots));
    out.canary = words(targetBytes, base + room, 1)[0];
    out.published = words(targetBytes, offsetsWord, tiles + 1);
    const std::vector<uint8_t> wordBytes = readbackBuffer(ctx, wordLayout);
    out.words = words(wordBytes, wordsFirst, tiles + 1);
    out.wordCanaries[0] = words(wordBytes, wordsFirst - 1, 1)[0];
    out.wordCanaries[1] = words(wordBytes, wordsFirst + tiles + 1, 1)[0];
    return out;
}

// Returns the tiles of the largest rectangle. fallbacks (when not -1): the runs the sort must
// have given its bitonic network.
uint32_t expectSameRuns(const Scene& scene, uint32_t w, uint32_t h, uint32_t tile,
                        uint32_t minLongest = 1, const la::BinningTuning& tuning = {},
                        int64_t fallbacks = -1) {
    auto ctx = makeValidatedContext();
    EXPECT_TRUE(ctx);
    if (!ctx) return 0;
    SceneGpu gpuScene(*ctx, scene);
    Binned b = bin(*ctx, gpuScene, w, h, tile, 2, ~0u, false, {}, tuning);
    if (tuning.fillReserve) {
        EXPECT_EQ(b.fillReserved, *tuning.fillReserve) << "the fill's variant";
    }
    EXPECT_EQ(b.sizes.bound, b.cpu.bound);
    EXPECT_EQ(b.sizes.offsets, b.cpu.offsets);
    EXPECT_EQ(b.sizes.slots, b.cpu.slots);
    EXPECT_EQ(b.sizes.maxBound, b.cpu.maxBound);
    EXPECT_EQ(b.offsets, b.cpu.offsets);
    EXPECT_EQ(b.published, b.cpu.offsets) << "the offsets the consumers read";
    EXPECT_FALSE(b.overflowed);
    EXPECT_EQ(b.canary, kCanary);
    EXPECT_EQ(b.corners, b.cpuCorners) << "light_binning's counted atomics (efficiency placement)";
    if (fallbacks >= 0) {
        EXPECT_EQ(b.fallbacks, uint64_t(fallbacks)) << "runs sorted by the network";
    }
    // The word layout: a bit per candidate and kWordsAdd more per tile (HybridBlended's masks).
    std::vector<uint32_t> wantWords(b.cpu.bound.size() + 1, 0);
    for (size_t t = 0; t < b.cpu.bound.size(); ++t)
        wantWords[t + 1] = wantWords[t] + (kWordsAdd + b.cpu.bound[t] + 31) / 32;
    EXPECT_EQ(b.words, wantWords);
    EXPECT_EQ(b.wordCanaries[0], kCanary);
    EXPECT_EQ(b.wordCanaries[1], kCanary);
    EXPECT_EQ(b.runs.size(), b.cpu.candidates.size());
    if (b.runs.size() != b.cpu.candidates.size()) return 0;
    const la::TileGrid grid = la::makeTileGrid(w, h, tile);
    uint32_t differing = 0;
    for (uint32_t t = 0; t < grid.count(); ++t)
        for (uint32_t i = b.cpu.offsets[t]; i < b.cpu.offsets[t + 1]; ++i)
            if (b.runs[i] != b.cpu.candidates[i]) ++differing;
    EXPECT_EQ(differing, 0u) << "of " << b.runs.size() << " candidates";
    EXPECT_GE(b.cpu.maxBound, minLongest);
    EXPECT_GT(b.cpu.slots, 0u);
    expectNoValidationMessages(*ctx);
    return b.largestRect;
}

TEST(GpuLightBinning, CourtyardPointsAndSpotsTile8) {
    expectSameRuns(courtyard(512), 128, 72, 8);
}
TEST(GpuLightBinning, CourtyardPointsAndSpotsTile16) {
    expectSameRuns(courtyard(512), 128, 72, 16);
}
TEST(GpuLightBinning, CourtyardPointsAndSpotsTile32) {
    expectSameRuns(courtyard(512), 160, 90, 32);
}
TEST(GpuLightBinning, Floor2048Lights) {
    expectSameRuns(floorWith(2048), 160, 96, 16);
}
// The fill with its workgroup's reserved shared memory (a GPU's choice with many lights a
// tile; lavapipe's never): the same runs. Large rectangles too (pairs split over workgroups).
TEST(GpuLightBinning, Floor2048LightsFillReserved) {
    expectSameRuns(floorWith(2048), 160, 96, 16, 1, {.fillReserve = true});
}
TEST(GpuLightBinning, LargeRectanglesFillReserved) {
    expectSameRuns(aroundTheEye(1024), 256, 160, 8, 1, {.fillReserve = true});
}

// Rows and columns longer than the scans' workgroup (64): each invocation scans a share of
// several tiles (12 x 150 tiles, then 150 x 12).
TEST(GpuLightBinning, TallAndWideGridsScanInShares) {
    expectSameRuns(floorWith(2048), 96, 1200, 8);
    expectSameRuns(floorWith(2048), 1200, 96, 8);
}
TEST(GpuLightBinning, LightsAroundAndBehindTheEye) {
    expectSameRuns(aroundTheEye(1024), 96, 64, 8);
}
// 1,000 lights in every tile: runs past the rank sort, by buckets in shared memory (four
// lights a bucket: 256 over the range of 1,000 light indices).
TEST(GpuLightBinning, WholeScreenRunsSortedInSharedMemory) {
    expectSameRuns(wholeScreen(1000), 48, 32, 16, TP_BIN_RANK_SORT + 1, {}, 0);
}
// The same runs over 16 buckets: 64 lights a bucket (TP_BIN_BUCKET_MOST; a bucket spans a
// power of two of the range's 10 bits), each ranked among its bucket's; over 8, 128 a bucket,
// too many: the bitonic network sorts each of the 3 x 2 tiles' runs instead.
constexpr uint32_t kWholeScreenBucket16 = 1u << (std::bit_width(999u) - 4);
constexpr uint32_t kWholeScreenBucket8 = 1u << (std::bit_width(999u) - 3);
TEST(GpuLightBinning, WholeScreenRunsInFullBuckets) {
    static_assert(kWholeScreenBucket16 == TP_BIN_BUCKET_MOST);
    expectSameRuns(wholeScreen(1000), 48, 32, 16, TP_BIN_RANK_SORT + 1, {.sortBuckets = 16}, 0);
}
TEST(GpuLightBinning, WholeScreenRunsInCrowdedBucketsSortedBitonic) {
    static_assert(kWholeScreenBucket8 > TP_BIN_BUCKET_MOST);
    expectSameRuns(wholeScreen(1000), 48, 32, 16, TP_BIN_RANK_SORT + 1, {.sortBuckets = 8}, 6);
}
// 4,500 lights in every one of 12 tiles: each run is sorted in place, one dispatch per step.
TEST(GpuLightBinning, WholeScreenRunsLongerThanSharedMemory) {
    expectSameRuns(wholeScreen(TP_BIN_SHARED_SORT + 404), 32, 24, 8, TP_BIN_SHARED_SORT + 1);
}
// Runs of 9,000 (sorted as 16,384): two merges past the block, each with steps at distances
// of a block or more (a dispatch each) and steps within the blocks (shared memory).
TEST(GpuLightBinning, WholeScreenRunsOfFourBlocks) {
    expectSameRuns(wholeScreen(2 * TP_BIN_SHARED_SORT + 808), 24, 16, 8,
                   2 * TP_BIN_SHARED_SORT + 1);
}

// Lights near the eye cover many tiles, others one: the fill spreads a workgroup's
// (light, tile) pairs over its invocations, in one dispatch; and in several (rows of tiles
// per dispatch).
TEST(GpuLightBinning, LargeAndSmallRectanglesShareAWorkgroup) {
    const uint32_t largest = expectSameRuns(aroundTheEye(1024), 256, 160, 8); // 32 x 20 tiles
    EXPECT_GT(largest, 64u); // more pairs than a workgroup has invocations
}
TEST(GpuLightBinning, LargeRectanglesOverSeveralFillDispatches) {
    // 2,048 x 24 tiles of 8: TP_BIN_FILL_BUDGET / 2,048 = 16 rows per dispatch, two dispatches.
    EXPECT_GT(expectSameRuns(aroundTheEye(64), 16384, 192, 8), TP_BIN_FILL_BUDGET);
}

// A view past the planned room: the frame cuts its runs at the room (nothing written past it,
// the published offsets clamped) and overflowed() says so, so the renderer is planned again.
TEST(GpuLightBinning, ViewPastTheRoomIsCutAndCounted) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const Scene scene = courtyard(512); // SceneGpu keeps a reference
    SceneGpu gpuScene(*ctx, scene);
    const Binned whole = bin(*ctx, gpuScene, 128, 72, 16);
    ASSERT_GT(whole.sizes.slots, 100u);
    const uint32_t room = uint32_t(whole.sizes.slots / 2);
    const Binned cut = bin(*ctx, gpuScene, 128, 72, 16, 2, room);
    EXPECT_TRUE(cut.overflowed);
    EXPECT_EQ(cut.canary, kCanary) << "a run written past the room";
    ASSERT_EQ(cut.published.size(), whole.sizes.offsets.size());
    for (size_t t = 0; t < cut.published.size(); ++t)
        EXPECT_EQ(cut.published[t], std::min(whole.sizes.offsets[t], room)) << "tile " << t;
    // Runs wholly inside the room are complete (and sorted).
    for (size_t t = 0; t + 1 < whole.sizes.offsets.size() && whole.sizes.offsets[t + 1] <= room;
         ++t)
        for (uint32_t i = whole.sizes.offsets[t]; i < whole.sizes.offsets[t + 1]; ++i)
            ASSERT_EQ(cut.runs[i], whole.cpu.candidates[i]) << "tile " << t;
    expectNoValidationMessages(*ctx);
}

// A view whose longest run is past the one the frame was recorded for (the sort's steps, the
// consumers' batches) is an overflow too: planned for the first view's, lights moved closer.
// Plans a single view of the courtyard's 512 lights at 128x72 (tiles of `tile`), then moves
// every light to the eye's target, so that the tiles there hold every light, and runs a frame
// of that view. Returns the binning, its graph and the first view's sizes.
struct LongerRun {
    std::unique_ptr<GpuContext> ctx;
    std::unique_ptr<SceneGpu> scene;
    std::unique_ptr<la::GpuBinning> bin;
    std::unique_ptr<FrameGraph> graph;
    Buffer target;
    la::LightBins first;
    uint32_t locals = 0;
};
void runLongerThanPlanned(LongerRun& r, uint32_t tile) {
    r.ctx = makeValidatedContext();
    ASSERT_TRUE(r.ctx);
    Scene scene = courtyard(512);
    r.scene = std::make_unique<SceneGpu>(*r.ctx, scene);
    r.scene->setView(128, 72, 1);
    const la::TileGrid grid = la::makeTileGrid(128, 72, tile);
    const std::vector<uint32_t> local = la::classifyLights(r.scene->shadingLights()).local;
    r.locals = uint32_t(local.size());
    r.bin = std::make_unique<la::GpuBinning>(*r.ctx, *r.scene, grid, local, "test");
    r.first = r.bin->sizes();
    EXPECT_EQ(r.bin->runBound(), r.first.maxBound); // a single view: exactly its need
    EXPECT_EQ(r.bin->sortSharedRun(),
              std::clamp(std::bit_ceil(r.first.maxBound), TP_BIN_SORT_SHARED_LEAST, TP_BIN_SHARED_SORT));
    ASSERT_LT(r.first.maxBound, local.size());
    for (Light& l : scene.lights)
        l.position = scene.camera.target;
    r.scene->setLights(scene.lights);
    r.scene->setView(128, 72, 1);
    const uint64_t room = uint64_t(local.size()) * grid.count();
    std::vector<uint32_t> zeros(room + grid.count() + 1, 0);
    r.target = createBufferWithData(*r.ctx, zeros.data(), zeros.size() * 4,
                                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                    {"test", "", "runs", "the runs, the offsets"});
    r.graph = std::make_unique<FrameGraph>(*r.ctx, "test", 128, 72);
    r.bin->plan(*r.graph);
    r.graph->compile();
    r.bin->prepare(*r.graph, r.target.buffer, 0, room, room);
    r.bin->followView();
    recordAndSubmit(*r.ctx, *r.graph, 1);
}

TEST(GpuLightBinning, RunLongerThanPlannedIsCounted) {
    LongerRun r;
    runLongerThanPlanned(r, 16);
    ASSERT_TRUE(r.graph);
    ASSERT_GE(r.bin->sortSharedRun(), r.locals) << "the case below needs the run to fit";
    EXPECT_TRUE(r.bin->overflowed(*r.graph, 1)); // a consumer taking a light per dispatch
    // One taking every light in one dispatch records the same for the longer run (and the sort
    // stays in shared memory): no replan for it.
    EXPECT_FALSE(r.bin->overflowed(*r.graph, r.locals));
    EXPECT_EQ(r.bin->collect(*r.graph).maxBound, r.locals);
    EXPECT_EQ(r.bin->sizingRuns(), 1u);
    expectNoValidationMessages(*r.ctx);
}
// The same with tiles of 8: the first view's runs fit the least shared run (256), the moved
// lights' 512 do not, so even a consumer of every light in one dispatch plans again (its runs
// were left unsorted).
TEST(GpuLightBinning, RunPastTheSortsSharedRunIsCounted) {
    LongerRun r;
    runLongerThanPlanned(r, 8);
    ASSERT_TRUE(r.graph);
    ASSERT_LT(r.bin->sortSharedRun(), r.locals);
    EXPECT_TRUE(r.bin->overflowed(*r.graph, r.locals));
    expectNoValidationMessages(*r.ctx);
}

// Clustered Forward+'s slice rows (ceil(run / 32) words a slice, `slices` rows a tile), laid
// out by the frame (publishWords, scale = slices) from a word inside a larger buffer (Forward+
// keeps them in fp_params): fp::layoutMasks's offsets, the layout the CPU made per view.
void expectCpuMaskRows(const Scene& scene, uint32_t w, uint32_t h, uint32_t tile, uint32_t slices) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    SceneGpu gpuScene(*ctx, scene);
    const Binned b = bin(*ctx, gpuScene, w, h, tile, 2, ~0u, false, {slices, 0, 37});
    const fp::MaskLayout want = fp::layoutMasks(b.cpu.bound, slices);
    EXPECT_EQ(b.words, want.offsets);
    EXPECT_GT(b.cpu.maxBound, 32u) << "rows of more than one word";
    EXPECT_EQ(b.wordCanaries[0], kCanary);
    EXPECT_EQ(b.wordCanaries[1], kCanary);
    EXPECT_FALSE(b.overflowed);
    expectNoValidationMessages(*ctx);
}

TEST(GpuLightBinning, ClusterMaskRowsEqualTheCpuLayoutCourtyard) {
    expectCpuMaskRows(courtyard(512), 128, 72, 8, 16);
}
TEST(GpuLightBinning, ClusterMaskRowsEqualTheCpuLayoutFloor64Slices) {
    expectCpuMaskRows(floorWith(2048), 160, 96, 16, 64);
}

// A view whose slice rows need more words than the plan holds (its runs fit): the row offsets
// are clamped to the room (the culling keeps no more lights than a clamped row holds bits:
// light_culling_common.glsl, arraySlots) and overflowed() says so.
TEST(GpuLightBinning, MaskRowsPastTheRoomAreClampedAndCounted) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const Scene scene = courtyard(512);
    SceneGpu gpuScene(*ctx, scene);
    const uint32_t slices = 16;
    const Binned whole = bin(*ctx, gpuScene, 128, 72, 16, 2, ~0u, false, {slices, 0, 5});
    const fp::MaskLayout want = fp::layoutMasks(whole.cpu.bound, slices);
    ASSERT_GT(want.words, 100u);
    EXPECT_FALSE(whole.overflowed);
    const uint32_t room = uint32_t(want.words / 2);
    const Binned cut = bin(*ctx, gpuScene, 128, 72, 16, 2, ~0u, false, {slices, 0, 5, room});
    EXPECT_TRUE(cut.overflowed) << "more words than the room";
    ASSERT_EQ(cut.words.size(), want.offsets.size());
    for (size_t t = 0; t < cut.words.size(); ++t)
        EXPECT_EQ(cut.words[t], std::min(want.offsets[t], room)) << "tile " << t;
    EXPECT_EQ(cut.published, whole.published) << "the runs fit: unchanged";
    EXPECT_EQ(cut.wordCanaries[1], kCanary);
    expectNoValidationMessages(*ctx);
}

TEST(GpuLightBinning, NoLocalLights) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const Scene scene = floorWith(0); // SceneGpu keeps a reference: not a temporary
    SceneGpu gpuScene(*ctx, scene);
    Binned b = bin(*ctx, gpuScene, 40, 24, 8);
    EXPECT_EQ(b.offsets, std::vector<uint32_t>(5 * 3 + 1, 0));
    EXPECT_EQ(b.sizes.slots, 0u);
    expectNoValidationMessages(*ctx);
}

// ---- the pipelines: --light-bin gpu renders what cpu renders ----

double counter(const RunResult& r, const std::string& name) {
    for (const auto& [n, v] : r.stats.counters)
        if (n == name) return v;
    return -1.0;
}

// Every registered renderer that reads --light-bin. The GPU's runs equal the CPU's (above),
// and each pipeline's lists keep their runs' order (tiled lighting compacts its survivors in
// ascending candidate order: passes/ordered_lists.glsl), so the images are the same byte for
// byte on any device.
void expectSameImages(const Scene& scene, RenderSettings s) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    SceneGpu gpuScene(*ctx, scene);
    size_t binning = 0;
    for (const RendererEntry& entry : registeredRenderers()) {
        auto reads = [](const Knob& k) { return k.name == "light-bin"; };
        if (std::none_of(entry.knobs.begin(), entry.knobs.end(), reads)) continue;
        ++binning;
        SCOPED_TRACE(entry.name);
        s.set("light-bin", "cpu");
        RunResult cpu = runOrFail(*ctx, gpuScene, entry.name, s);
        s.set("light-bin", "gpu");
        RunResult gpu = runOrFail(*ctx, gpuScene, entry.name, s, 2);
        EXPECT_EQ(cpu.hdr.rgba, gpu.hdr.rgba);
        EXPECT_EQ(counter(cpu, "light_binning_on_gpu"), 0.0);
        EXPECT_EQ(counter(gpu, "light_binning_on_gpu"), 1.0);
        EXPECT_EQ(std::count(gpu.passes.begin(), gpu.passes.end(), "light_binning"), 1);
        EXPECT_EQ(std::count(cpu.passes.begin(), cpu.passes.end(), "light_binning"), 0);
    }
    EXPECT_GT(binning, 0u) << "no registered renderer reads --light-bin";
    expectNoValidationMessages(*ctx);
}

RenderSettings settings(uint32_t w, uint32_t h, uint32_t msaa, uint32_t tile) {
    RenderSettings s;
    s.width = w;
    s.height = h;
    s.msaa = msaa;
    s.set("tile", tile);
    // Binned: --light-cull auto is `all` on a GPU up to 2,048 lights (no binning to compare).
    s.set("light-cull", "binned");
    return s;
}

TEST(GpuLightBinning, ImagesEqualCpuBinningCourtyard) {
    expectSameImages(courtyard(512), settings(96, 54, 1, 16));
}
TEST(GpuLightBinning, ImagesEqualCpuBinningMsaa4Tile8) {
    expectSameImages(courtyard(256), settings(96, 54, 4, 8));
}
TEST(GpuLightBinning, ImagesEqualCpuBinningFloorTile32Clustered) {
    RenderSettings s = settings(128, 80, 1, 32);
    s.set("light-assign", "clustered");
    expectSameImages(floorWith(2048), s);
}

// auto: cpu on a CPU device (lavapipe), gpu on any other.
TEST(GpuLightBinning, AutoResolvesByDeviceType) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const Scene scene = courtyard(16); // SceneGpu keeps a reference: not a temporary
    SceneGpu gpuScene(*ctx, scene);
    RunResult r = runOrFail(*ctx, gpuScene, "forwardplus", settings(48, 27, 1, 16));
    EXPECT_EQ(counter(r, "light_binning_on_gpu"), ctx->isCpuDevice() ? 0.0 : 1.0);
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
