// Light assignment's CPU half (core/lightassign): the tile grid, light classes, the compact
// layout's prefix sum, the conservative per-tile bound and the one heat-map scale.
#include <gtest/gtest.h>

#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "core/lightassign/compact_layout.h"
#include "core/lightassign/light_classes.h"
#include "core/lightassign/tile_bound.h"
#include "core/lightassign/tile_candidates.h"
#include "core/lightassign/tile_grid.h"
#include "core/passes/debug_views.h"

using namespace tp;

namespace {

gpu::LightGpu pointLight(glm::vec3 position, float range) {
    gpu::LightGpu l{};
    l.position = position;
    l.range = range;
    l.type = TP_LIGHT_POINT;
    return l;
}

// Tiles that some point of the light's sphere projects into (a lattice of points inside
// it, in front of the near plane): a lower bound on the tiles the light truly reaches.
std::vector<uint32_t> sampledTiles(const la::TileGrid& g, const glm::mat4& proj,
                                   const gpu::LightGpu& l) {
    std::vector<uint32_t> hit(g.count(), 0);
    const int n = 8;
    for (int i = -n; i <= n; ++i)
        for (int j = -n; j <= n; ++j)
            for (int k = -n; k <= n; ++k) {
                glm::vec3 d = glm::vec3(i, j, k) / float(n);
                if (glm::dot(d, d) > 1.0f) continue;
                glm::vec3 p = l.position + d * l.range * 0.999f;
                if (p.z > -0.1f) continue; // behind the near plane
                glm::vec4 c = proj * glm::vec4(p, 1.0f);
                glm::vec2 ndc = glm::vec2(c) / c.w;
                float px = (ndc.x + 1.0f) * 0.5f * float(g.width),
                      py = (1.0f - ndc.y) * 0.5f * float(g.height);
                if (px < 0.0f || py < 0.0f || px >= float(g.width) || py >= float(g.height))
                    continue;
                hit[g.tileOf(uint32_t(px), uint32_t(py))] = 1;
            }
    return hit;
}

} // namespace

TEST(LightAssign, TileGridCoversTheViewportWithPartialTiles) {
    la::TileGrid g = la::makeTileGrid(1920, 1080, 16);
    EXPECT_EQ(g.tilesX, 120u);
    EXPECT_EQ(g.tilesY, 68u); // 1080 / 16 = 67.5: the last row is half a tile
    EXPECT_EQ(g.count(), 8160u);
    la::TileGrid p = la::makeTileGrid(100, 50, 32);
    EXPECT_EQ(p.tilesX, 4u);
    EXPECT_EQ(p.tilesY, 2u);
    EXPECT_EQ(p.tileOf(0, 0), 0u);
    EXPECT_EQ(p.tileOf(31, 31), 0u);
    EXPECT_EQ(p.tileOf(32, 0), 1u);
    EXPECT_EQ(p.tileOf(99, 49), 7u); // bottom-right pixel in the partial corner tile
}

TEST(LightAssign, ClassesSplitDirectionalFromLocalInIndexOrder) {
    std::vector<gpu::LightGpu> lights(5);
    lights[0].type = TP_LIGHT_POINT;
    lights[1].type = TP_LIGHT_DIRECTIONAL;
    lights[2].type = TP_LIGHT_SPOT;
    lights[3].type = TP_LIGHT_DIRECTIONAL;
    lights[4].type = TP_LIGHT_POINT;
    la::LightClasses c = la::classifyLights(lights);
    EXPECT_EQ(c.directional, (std::vector<uint32_t>{1, 3}));
    EXPECT_EQ(c.local, (std::vector<uint32_t>{0, 2, 4}));
}

TEST(LightAssign, CompactLayoutIsTheExclusivePrefixSum) {
    la::CompactLayout c = la::makeCompactLayout({3, 0, 5, 1});
    EXPECT_EQ(c.offsets, (std::vector<uint32_t>{0, 3, 3, 8, 9}));
    EXPECT_EQ(c.slots, 9u);
    // Lights that every list holds (directional, unculled) add to every tile's run.
    la::CompactLayout d = la::makeCompactLayout({3, 0, 5, 1}, 2);
    EXPECT_EQ(d.offsets, (std::vector<uint32_t>{0, 5, 7, 14, 17}));
    EXPECT_EQ(d.slots, 17u);
    la::CompactLayout e = la::makeCompactLayout({});
    EXPECT_EQ(e.offsets, (std::vector<uint32_t>{0}));
    EXPECT_EQ(e.slots, 0u);
}

TEST(LightAssign, CompactLayoutReportsSlotsBeyond32Bits) {
    // The offsets clamp, the total does not: the caller refuses such a layout by `slots`.
    std::vector<uint32_t> bound(3, 0x80000000u);
    la::CompactLayout c = la::makeCompactLayout(bound);
    EXPECT_EQ(c.slots, 3ull * 0x80000000ull);
    EXPECT_EQ(c.offsets.back(), 0xffffffffu);
}

TEST(LightAssign, ConservativeBoundIsNeverBelowTheLightsThatReachATile) {
    la::TileGrid g = la::makeTileGrid(200, 120, 16);
    glm::mat4 view(1.0f);
    glm::mat4 proj = glm::perspective(glm::radians(60.0f), 200.0f / 120.0f, 0.1f, 100.0f);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> x(-12.0f, 12.0f), y(-8.0f, 8.0f), z(-20.0f, 2.0f),
        r(0.2f, 4.0f);
    std::vector<gpu::LightGpu> lights;
    for (int i = 0; i < 300; ++i)
        lights.push_back(pointLight({x(rng), y(rng), z(rng)}, r(rng)));
    lights.push_back(pointLight({0.0f, 0.0f, 0.0f}, 1.0f)); // the eye inside: every tile
    std::vector<uint32_t> local(lights.size());
    for (uint32_t i = 0; i < local.size(); ++i)
        local[i] = i;
    std::vector<uint32_t> bound = la::conservativeTileBound(g, view, proj, lights, local);
    ASSERT_EQ(bound.size(), g.count());
    std::vector<uint32_t> truth(g.count(), 0);
    for (const gpu::LightGpu& l : lights) {
        std::vector<uint32_t> hit = sampledTiles(g, proj, l);
        for (uint32_t t = 0; t < g.count(); ++t)
            truth[t] += hit[t];
    }
    uint64_t boundSum = 0, truthSum = 0;
    for (uint32_t t = 0; t < g.count(); ++t) {
        EXPECT_GE(bound[t], truth[t]) << "tile " << t;
        EXPECT_GE(bound[t], 1u) << "the light around the eye reaches tile " << t;
        boundSum += bound[t];
        truthSum += truth[t];
    }
    // Conservative, not useless: a bound far above the truth would waste the layout.
    EXPECT_LT(double(boundSum), 3.0 * double(truthSum));
}

TEST(LightAssign, ConservativeBoundSkipsLightsBehindTheEye) {
    la::TileGrid g = la::makeTileGrid(64, 64, 16);
    glm::mat4 proj = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
    std::vector<gpu::LightGpu> lights = {pointLight({0.0f, 0.0f, 5.0f}, 1.0f)};
    std::vector<uint32_t> bound = la::conservativeTileBound(g, glm::mat4(1.0f), proj, lights, {0});
    for (uint32_t b : bound)
        EXPECT_EQ(b, 0u);
}

// Binned culling's candidates: each tile's run holds exactly the lights whose rectangle
// covers it, ascending, and the runs are the compact layout of the rectangle counts.
TEST(LightAssign, TileCandidatesAreEachTilesCoveringLightsAscending) {
    la::TileGrid g = la::makeTileGrid(200, 120, 16); // 13 x 8 tiles
    glm::mat4 proj = glm::perspective(glm::radians(60.0f), 200.0f / 120.0f, 0.1f, 100.0f);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> x(-12.0f, 12.0f), y(-8.0f, 8.0f), z(-20.0f, 2.0f),
        r(0.2f, 4.0f);
    std::vector<gpu::LightGpu> lights;
    for (int i = 0; i < 200; ++i)
        lights.push_back(pointLight({x(rng), y(rng), z(rng)}, r(rng)));
    // Local lights are a subset (as when directional lights are interleaved), not 0..n-1.
    std::vector<uint32_t> local;
    for (uint32_t i = 0; i < lights.size(); i += 2)
        local.push_back(i);
    std::vector<la::TileRect> rects =
        la::conservativeTileRects(g, glm::mat4(1.0f), proj, lights, local);
    ASSERT_EQ(rects.size(), local.size());
    std::vector<uint32_t> counts = la::countTileRects(g, rects);
    EXPECT_EQ(counts, la::conservativeTileBound(g, glm::mat4(1.0f), proj, lights, local));
    la::CompactLayout layout = la::makeCompactLayout(counts);
    std::vector<uint32_t> cand = la::tileCandidates(g, rects, local, layout.offsets);
    ASSERT_EQ(cand.size(), layout.slots);
    uint64_t covered = 0;
    for (uint32_t ty = 0; ty < g.tilesY; ++ty)
        for (uint32_t tx = 0; tx < g.tilesX; ++tx) {
            uint32_t t = ty * g.tilesX + tx;
            std::vector<uint32_t> expect;
            for (size_t k = 0; k < rects.size(); ++k)
                if (int(tx) >= rects[k].x0 && int(tx) <= rects[k].x1 && int(ty) >= rects[k].y0 &&
                    int(ty) <= rects[k].y1)
                    expect.push_back(local[k]);
            std::vector<uint32_t> got(cand.begin() + layout.offsets[t],
                                      cand.begin() + layout.offsets[t + 1]);
            EXPECT_EQ(got, expect) << "tile " << t;
            covered += expect.size();
        }
    EXPECT_GT(covered, 0u);
    EXPECT_LT(covered, uint64_t(local.size()) * g.count() / 2); // binning skips most pairs here
}

TEST(LightAssign, HeatMapHasOneScaleFromZeroToTheLargestCount) {
    EXPECT_EQ(passes::heatMapScaleMax({}), 1u);
    EXPECT_EQ(passes::heatMapScaleMax({0, 0}), 1u); // empty map: black, not a division by 0
    EXPECT_EQ(passes::heatMapScaleMax({3, 7, 2}), 7u);

    la::TileGrid g = la::makeTileGrid(32, 16, 8); // 4 x 2 tiles
    std::vector<uint32_t> counts = {0, 7, 3, 7, 0, 1, 2, 3};
    ImageRGBA img = passes::lightsPerTileHeatMap(g, counts);
    ASSERT_EQ(img.width, 32u);
    ASSERT_GT(img.height, 16u); // the legend strip under the map
    auto same = [&](uint32_t ax, uint32_t ay, uint32_t bx, uint32_t by) {
        for (int c = 0; c < 4; ++c)
            if (img.at(ax, ay)[c] != img.at(bx, by)[c]) return false;
        return true;
    };
    EXPECT_TRUE(same(9, 1, 25, 6));   // both 7 lights: the top of the scale
    EXPECT_TRUE(same(0, 0, 3, 12));   // both 0 lights
    EXPECT_FALSE(same(0, 0, 9, 1));   // 0 and 7 differ
    EXPECT_TRUE(same(16, 0, 31, 15)); // both 3 lights
    // The same counts on a map whose largest count is 14 use the upper half of the scale
    // for 7: the scale is relative to the map's largest count.
    std::vector<uint32_t> doubled = counts;
    doubled[0] = 14;
    ImageRGBA other = passes::lightsPerTileHeatMap(g, doubled);
    EXPECT_NE(other.at(9, 1)[0] + other.at(9, 1)[1] + other.at(9, 1)[2],
              img.at(9, 1)[0] + img.at(9, 1)[1] + img.at(9, 1)[2]);
}

TEST(LightAssign, HeatMapOutlinesTilesThatDroppedLights) {
    la::TileGrid g = la::makeTileGrid(32, 16, 8);
    std::vector<uint32_t> counts(8, 2), dropped(8, 0);
    dropped[5] = 1; // tile (1, 1): pixels x 8..15, y 8..15
    ImageRGBA img = passes::lightsPerTileHeatMap(g, counts, dropped);
    EXPECT_EQ(img.at(8, 8)[1], 1.0f);
    EXPECT_EQ(img.at(8, 8)[0], 0.0f);
    EXPECT_EQ(img.at(15, 12)[1], 1.0f);
    ImageRGBA plain = passes::lightsPerTileHeatMap(g, counts);
    for (int c = 0; c < 4; ++c)
        EXPECT_EQ(img.at(11, 11)[c], plain.at(11, 11)[c]); // inside: unchanged
}
