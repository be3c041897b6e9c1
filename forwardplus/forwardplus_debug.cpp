#include "forwardplus/forwardplus_debug.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "core/image/difference.h"
#include "core/lightassign/heat_map.h"

namespace tp::fp {

TileListSummary summarize(const std::vector<gpu::FpTileLists>& tiles, uint32_t list, bool testsSky,
                          size_t localLights, const std::vector<uint32_t>& candidates) {
    TileListSummary s;
    for (size_t i = 0; i < tiles.size(); ++i) {
        const gpu::FpTileLists& t = tiles[i];
        bool sky = t.nearDepth <= 0.0f;
        s.skyTiles += sky;
        if (testsSky || !sky) s.tested += double(candidates.empty() ? localLights : candidates[i]);
        s.stored += t.list[list].count;
        s.dropped += t.list[list].dropped;
        s.max = std::max(s.max, t.list[list].count);
    }
    s.passed = s.stored + s.dropped;
    s.mean = tiles.empty() ? 0.0 : s.stored / double(tiles.size());
    return s;
}

namespace {

// Lights in tile t's cluster of slice `sl`: the set bits of its row (read-back masks).
uint32_t clusterLights(const std::vector<gpu::FpTileLists>& tiles, const std::vector<uint32_t>& maskOffsets,
                       const std::vector<uint32_t>& masks, uint32_t slices, size_t t, uint32_t sl) {
    const uint32_t stride = (maskOffsets[t + 1] - maskOffsets[t]) / slices;
    const uint32_t words = std::min((tiles[t].list[0].count + 31) / 32, stride);
    uint32_t n = 0;
    for (uint32_t w = 0; w < words; ++w) {
        const size_t i = size_t(maskOffsets[t]) + size_t(sl) * stride + w;
        if (i < masks.size()) n += uint32_t(std::popcount(masks[i]));
    }
    return n;
}

} // namespace

ClusterSummary summarizeClusters(const std::vector<gpu::FpTileLists>& tiles, const std::vector<uint32_t>& maskOffsets,
                                 const std::vector<uint32_t>& masks, uint32_t slices) {
    ClusterSummary s;
    double clusters = 0.0, inClusters = 0.0;
    for (size_t t = 0; t + 1 < maskOffsets.size() && t < tiles.size(); ++t)
        for (uint32_t sl = 0; sl < slices; ++sl) {
            const uint32_t n = clusterLights(tiles, maskOffsets, masks, slices, t, sl);
            s.bits += n;
            s.max = std::max(s.max, n);
            if (tiles[t].nearDepth > 0.0f) {
                clusters += 1.0;
                inClusters += n;
            }
        }
    s.mean = clusters > 0.0 ? inClusters / clusters : 0.0;
    return s;
}

ClusterSummary summarizeFrontClusters(const std::vector<gpu::FpTileLists>& tiles,
                                      const std::vector<uint32_t>& maskOffsets, const std::vector<uint32_t>& masks,
                                      uint32_t slices, uint32_t frontSlices) {
    ClusterSummary s;
    double clusters = 0.0;
    for (size_t t = 0; t + 1 < maskOffsets.size() && t < tiles.size(); ++t) {
        if (!(tiles[t].frontNear < tiles[t].sliceNear)) continue;
        for (uint32_t sl = 0; sl < frontSlices; ++sl) {
            const uint32_t n = clusterLights(tiles, maskOffsets, masks, slices, t, sl);
            s.bits += n;
            s.max = std::max(s.max, n);
            clusters += 1.0;
        }
    }
    s.mean = clusters > 0.0 ? s.bits / clusters : 0.0;
    return s;
}

ImageRGBA lightsPerTileHeatMap(const la::TileGrid& g, const std::vector<gpu::FpTileLists>& tiles, uint32_t list) {
    std::vector<uint32_t> counts(tiles.size()), dropped(tiles.size());
    for (size_t t = 0; t < tiles.size(); ++t) {
        counts[t] = tiles[t].list[list].count;
        dropped[t] = tiles[t].list[list].dropped;
    }
    return la::lightsPerTileHeatMap(g, counts, dropped);
}

ImageRGBA tileDepthBoundsImage(const la::TileGrid& g, const std::vector<gpu::FpTileLists>& tiles,
                               const glm::mat4& invProj) {
    auto distance = [&](float depth) {
        glm::vec4 v = invProj * glm::vec4(0.0f, 0.0f, depth, 1.0f);
        return std::abs(v.w) < 1e-30f ? std::numeric_limits<float>::infinity() : -v.z / v.w;
    };
    const uint32_t gap = 4;
    ImageRGBA values(2 * g.width + gap, g.height);
    float farthest = 0.0f;
    for (const gpu::FpTileLists& t : tiles)
        if (t.nearDepth > 0.0f) farthest = std::max(farthest, distance(t.farDepth));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (uint32_t y = 0; y < g.height; ++y)
        for (uint32_t x = 0; x < g.width; ++x) {
            const gpu::FpTileLists& t = tiles[(y / g.tileSize) * g.tilesX + x / g.tileSize];
            bool sky = t.nearDepth <= 0.0f;
            float n = sky ? nan : distance(t.nearDepth), f = sky ? nan : distance(t.farDepth);
            float* a = values.at(x, y);
            float* b = values.at(g.width + gap + x, y);
            a[0] = a[1] = a[2] = n;
            b[0] = b[1] = b[2] = f;
            a[3] = b[3] = 1.0f;
        }
    return heatMap(values, farthest > 0.0f && std::isfinite(farthest) ? farthest : 1.0f);
}

} // namespace tp::fp
