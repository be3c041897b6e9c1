// la::binLights: the one binning both Forward+ and tiled deferred upload must equal its
// parts (rectangles -> counts -> compact layout -> candidates), so folding them changed nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "core/lightassign/compact_layout.h"
#include "core/lightassign/corner_atomics.h"
#include "core/lightassign/light_bins.h"
#include "core/lightassign/tile_bound.h"
#include "core/lightassign/tile_candidates.h"

using namespace tp;

TEST(LightBins, EqualTheirPartsAndBuildCandidatesOnlyWhenAsked) {
    la::TileGrid g = la::makeTileGrid(200, 120, 16); // 13 x 8 tiles
    glm::mat4 view = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, -0.25f, -1.0f));
    glm::mat4 proj = glm::perspective(glm::radians(60.0f), 200.0f / 120.0f, 0.1f, 100.0f);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> x(-12.0f, 12.0f), y(-8.0f, 8.0f), z(-20.0f, 2.0f),
        r(0.2f, 4.0f);
    std::vector<gpu::LightGpu> lights(150);
    for (gpu::LightGpu& l : lights) {
        l.position = {x(rng), y(rng), z(rng)};
        l.range = r(rng);
        l.type = TP_LIGHT_POINT;
    }
    std::vector<uint32_t> local;
    for (uint32_t i = 1; i < lights.size(); i += 3)
        local.push_back(i);

    std::vector<la::TileRect> rects = la::conservativeTileRects(g, view, proj, lights, local);
    std::vector<uint32_t> bound = la::countTileRects(g, rects);
    la::CompactLayout layout = la::makeCompactLayout(bound);
    std::vector<uint32_t> cand = la::tileCandidates(g, rects, local, layout.offsets);

    la::LightBins bins = la::binLights(g, view, proj, lights, local, true);
    EXPECT_EQ(bins.bound, bound);
    EXPECT_EQ(bins.offsets, layout.offsets);
    EXPECT_EQ(bins.slots, layout.slots);
    EXPECT_EQ(bins.candidates, cand);
    EXPECT_EQ(bins.maxBound, *std::max_element(bound.begin(), bound.end()));
    EXPECT_GT(bins.maxBound, 0u);

    la::LightBins noCand = la::binLights(g, view, proj, lights, local, false);
    EXPECT_TRUE(noCand.candidates.empty());
    EXPECT_EQ(noCand.offsets, layout.offsets);
    EXPECT_EQ(noCand.maxBound, bins.maxBound);
}

// bin_rects.comp's atomics, rectangle by rectangle on a 4 x 4 grid: the corners inside the
// grid, or the tiles where a rectangle has fewer tiles than corners.
TEST(LightBins, CornerAtomicsAreTheFewerOfCornersAndTiles) {
    const la::TileGrid g = la::makeTileGrid(64, 64, 16);
    ASSERT_EQ(g.tilesX, 4u);
    ASSERT_EQ(g.tilesY, 4u);
    struct Case {
        la::TileRect r;
        uint64_t atomics;
    };
    const Case cases[] = {
        {{1, 1, 1, 1}, 1}, // 1x1 inside: 4 corners, 1 tile
        {{3, 3, 3, 3}, 1}, // the last tile: 1 corner
        {{3, 3, 1, 1}, 1}, // 1x1 on the last column: 2 corners, 1 tile
        {{0, 2, 1, 1}, 3}, // 1x3 inside: 4 corners, 3 tiles
        {{1, 2, 1, 2}, 4}, // 2x2 inside: 4 and 4
        {{0, 3, 1, 1}, 2}, // a whole row: 2 corners (first tile, below), 4 tiles
        {{0, 3, 0, 3}, 1}, // the whole grid: its first tile
        {{1, 2, 0, 3}, 2}, // two whole columns: 2 corners, 8 tiles
        {{2, 1, 0, 0}, 0}, // empty
    };
    uint64_t sum = 0;
    std::vector<la::TileRect> all;
    for (const Case& c : cases) {
        EXPECT_EQ(la::binCornerAtomics({c.r}, g), c.atomics)
            << c.r.x0 << ".." << c.r.x1 << " x " << c.r.y0 << ".." << c.r.y1;
        sum += c.atomics;
        all.push_back(c.r);
    }
    EXPECT_EQ(la::binCornerAtomics(all, g), sum);
}

TEST(LightBins, NoLightsGiveEmptyBins) {
    la::TileGrid g = la::makeTileGrid(64, 32, 16);
    la::LightBins bins = la::binLights(g, glm::mat4(1.0f), glm::mat4(1.0f), {}, {}, true);
    EXPECT_EQ(bins.bound, std::vector<uint32_t>(g.count(), 0));
    EXPECT_EQ(bins.offsets, std::vector<uint32_t>(g.count() + 1, 0));
    EXPECT_EQ(bins.slots, 0u);
    EXPECT_TRUE(bins.candidates.empty());
    EXPECT_EQ(bins.maxBound, 0u);
}

// The slab planes the GPU binning uploads (include/light_binning.h: BinInputs.slabs):
// columns lo, columns hi, rows lo, rows hi, unit normals pointing into their slab.
TEST(LightBins, SlabPlanesAreLaidOutAsTheGpuReadsThem) {
    la::TileGrid g = la::makeTileGrid(200, 120, 16); // 13 x 8 tiles
    glm::mat4 proj = glm::perspective(glm::radians(60.0f), 200.0f / 120.0f, 0.1f, 100.0f);
    std::vector<glm::vec4> p = la::binSlabPlanes(g, proj);
    ASSERT_EQ(p.size(), size_t(2 * (13 + 8)));
    for (const glm::vec4& q : p)
        EXPECT_NEAR(glm::length(glm::vec3(q)), 1.0f, 1e-6f);
    // A point straight ahead (ndc 0, 0: pixel 100, 60) lies in column 6 and row 3 (pixel rows
    // 48-63): inside column 6's two planes and row 3's lower one, outside column 0's right edge.
    const glm::vec3 ahead(0.0f, 0.0f, -5.0f);
    auto d = [&](uint32_t i) { return glm::dot(glm::vec3(p[i]), ahead) + p[i].w; };
    EXPECT_GT(d(6), 0.0f);      // column 6, "x >= its left edge"
    EXPECT_GT(d(13 + 6), 0.0f); // column 6, "x <= its right edge"
    EXPECT_LT(d(13 + 0), 0.0f); // column 0's right edge is left of the centre
    EXPECT_GT(d(26 + 3), 0.0f); // row 3 (from the top): "ndc y >= its lower edge"
}
