#include "forwardplus/forwardplus_debug.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "core/image/difference.h"
#include "core/passes/debug_views.h"

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
uint32_t clusterLights(const std::vector<gpu::FpTileLists>& tiles,
                       const std::vector<uint32_t>& maskOffsets, const std::vector<uint32_t>& masks,
                       uint32_t slices, size_t t, uint32_t sl) {
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

ClusterSummary summarizeClusters(const std::vector<gpu::FpTileLists>& tiles,
                                 const std::vector<uint32_t>& maskOffsets,
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
                                      const std::vector<uint32_t>& maskOffsets,
                                      const std::vector<uint32_t>& masks, uint32_t slices,
                                      uint32_t frontSlices) {
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

ImageRGBA lightsPerTileHeatMap(const la::TileGrid& g, const std::vector<gpu::FpTileLists>& tiles,
                               uint32_t list) {
    std::vector<uint32_t> counts(tiles.size()), dropped(tiles.size());
    for (size_t t = 0; t < tiles.size(); ++t) {
        counts[t] = tiles[t].list[list].count;
        dropped[t] = tiles[t].list[list].dropped;
    }
    return passes::lightsPerTileHeatMap(g, counts, dropped);
}

ImageRGBA tileDepthBoundsImage(const la::TileGrid& g, const std::vector<gpu::FpTileLists>& tiles,
                               const glm::mat4& invProj) {
    std::vector<passes::TileDepthRange> ranges(tiles.size());
    for (size_t i = 0; i < tiles.size(); ++i)
        ranges[i] = {tiles[i].nearDepth, tiles[i].farDepth};
    return passes::tileDepthBoundsImage(g, ranges, invProj);
}

} // namespace tp::fp
