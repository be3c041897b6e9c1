#include "core/passes/hybrid_blended.h"

#include <algorithm>

#include "core/gpu/context.h"
#include "core/gpu/readback.h"
#include "core/passes/blended_lists.h"
#include "core/passes/debug_views.h"
#include "core/renderer/renderer.h"
#include "passes/tiled_lighting.h"

namespace tp {

void HybridBlended::planLists(FrameGraph& graph, TiledLighting& lighting, TiledLightingTargets& t,
                              bool binned, uint32_t slices, bool sliceRows, bool manyViews,
                              bool composited) {
    const uint32_t tiles = t.grid.count();
    // Compact: each tile's run is sized by a conservative bound, so nothing can drop (a drop
    // would be counted in the tile's header, never silent). Binned: the lights binned once
    // (tiled lighting's candidates) and the lists sized from the same bound, a slot per
    // candidate: light indices, read by the blended pass as Forward+ reads its lists (a
    // bitmask over the candidates, a bit each, cost that pass 3.34 against 2.88 ms on the
    // H200: docs/deferred.md). Composited in the tiled pass, binned: the bitmasks, which it
    // walks one batch of candidates at a time.
    const std::vector<uint32_t>* bound = binned ? &lighting.bound(t.grid, graph.owner()) : nullptr;
    TransparentListPlan lists =
        planTransparentLists(t.grid, scene_, ctx_.caps.maxStorageBufferRange, ctx_.info.name,
                             binned && composited, bound, graph.owner(), manyViews);
    binned_ = binned;
    t.transparentLists = graph.createBuffer(
        "transparent_lists", lists.bytes(),
        lists.masks ? "per tile: list header, then a bitmask over its binned candidates"
                    : "per tile: list header, then packed transparent light indices");
    masks_ = lists.masks;
    t.listOffsets = std::move(lists.offsets);
    slots_ = lists.slots;
    capacity_ = lists.capacity;
    if (slices == 0 || !sliceRows) return;
    // Clustered: slice rows over the lists for the blended pass (passes/tiled_lighting.h:
    // tlClusterRowsBase).
    const uint64_t rowWords = lists.masks ? lists.capacity : lists.capacity / 32 + tiles;
    const uint64_t words = 2ull * tiles + uint64_t(slices) * rowWords;
    if (words * 4 > ctx_.caps.maxStorageBufferRange)
        throw RendererError(graph.owner() + ": the transparent slice rows need " +
                            std::to_string(words * 4) +
                            " bytes, more than maxStorageBufferRange of " + ctx_.info.name +
                            "; use fewer --slices, a larger --tile or fewer lights");
    sliceRows_ = graph.createBuffer(
        "transparent_cluster_masks", words * 4,
        lists.masks ? "per tile: slicing, then per slice a bitmask row over its binned candidates"
                    : "per tile: slicing, then per slice a bitmask row over its transparent list");
}

bool HybridBlended::updateLists(TiledLighting& lighting, TiledLightingTargets& t) {
    // GPU binning: the frame lays the lists out (prepare); overflow is checked after it.
    if (binned_ && lighting.gpuBinning()) return true;
    const std::vector<uint32_t>* bound = binned_ ? &lighting.bound(t.grid, "") : nullptr;
    TransparentListPlan lists = transparentListNeed(t.grid, scene_, masks_, bound);
    if (lists.slots > capacity_) return false;
    slots_ = lists.slots;
    t.listOffsets = std::move(lists.offsets);
    lighting.setListOffsets(t.listOffsets);
    return true;
}

ResourceHandle HybridBlended::planBounds(FrameGraph& graph, const la::BlendedBoundsConfig& config) {
    return bounds_.plan(graph, config);
}

void HybridBlended::planForward(FrameGraph& graph, const BlendedForwardTargets& t,
                                uint32_t slices) {
    forward_.plan(graph, t, slices, sliceRows_);
    forwardPlanned_ = true;
}

void HybridBlended::prepare(FrameGraph& graph, TiledLighting& lighting) {
    bounds_.prepare(graph);
    if (binned_ && lighting.gpuBinning()) lighting.publishListWords(capacity_, masks_);
    if (forwardPlanned_) forward_.prepare(graph, binned_, lighting.lightsUbo());
}

namespace {

// Transparent lights per tile, kept and dropped: the tile statistics hold what each tile's
// test found (the count before its list was cut), the compact layout each tile's run, so
// these equal the list headers' count and dropped without reading the lists back.
struct TransparentCounts {
    std::vector<uint32_t> kept, dropped;
};

// masks: the runs are bitmasks over every candidate, so every light found is kept.
TransparentCounts transparentCounts(const std::vector<uint32_t>& stats,
                                    const std::vector<uint32_t>& offsets, bool masks) {
    TransparentCounts c;
    const size_t tiles = std::min(stats.size() / 4, offsets.empty() ? 0 : offsets.size() - 1);
    c.kept.resize(tiles);
    c.dropped.resize(tiles);
    for (size_t t = 0; t < tiles; ++t) {
        uint32_t found = stats[t * 4 + 1], run = offsets[t + 1] - offsets[t];
        c.kept[t] = masks ? found : std::min(found, run);
        c.dropped[t] = found - c.kept[t];
    }
    return c;
}

} // namespace

ImageRGBA HybridBlended::heatMap(const la::TileGrid& grid, const std::vector<uint32_t>& tileStats,
                                 const std::vector<uint32_t>& listOffsets) const {
    TransparentCounts c = transparentCounts(tileStats, listOffsets, masks_);
    return passes::lightsPerTileHeatMap(grid, c.kept, c.dropped);
}

void HybridBlended::addStats(RendererStats& s, const std::vector<uint32_t>& tileStats,
                             const std::vector<uint32_t>& listOffsets) const {
    TransparentCounts c = transparentCounts(tileStats, listOffsets, masks_);
    double kept = 0, dropped = 0, most = 0, listed = 0;
    for (size_t t = 0; t < c.kept.size(); ++t) {
        kept += c.kept[t];
        dropped += c.dropped[t];
        most = std::max(most, double(c.kept[t]));
        listed += c.kept[t] > 0;
    }
    // Blended fragments lie in few tiles: the mean over the tiles whose list holds a light is
    // what a blended fragment evaluates (docs/efficiency.md), not the mean over every tile.
    s.counters.push_back({"transparent_lights_per_nonempty_tile_mean", listed > 0 ? kept / listed : 0.0});
    s.counters.push_back(
        {"transparent_lights_per_tile_mean", c.kept.empty() ? 0.0 : kept / double(c.kept.size())});
    s.counters.push_back({"transparent_lights_per_tile_max", most});
    // Index slots, or (binned) bitmask words over the candidates.
    s.counters.push_back(
        {masks_ ? "transparent_list_mask_words" : "transparent_list_slots", double(slots_)});
    s.counters.push_back({"transparent_lights_stored", kept});
    s.counters.push_back({"transparent_lights_dropped", dropped}); // 0: the bound is conservative
}

std::vector<uint32_t> tileStatColumn(const std::vector<uint32_t>& stats, uint32_t c) {
    std::vector<uint32_t> out(stats.size() / 4);
    for (size_t t = 0; t < out.size(); ++t)
        out[t] = stats[t * 4 + c];
    return out;
}

void appendTiledLightingDebug(GpuContext& ctx, FrameGraph& graph, const TiledLightingTargets& t,
                              const std::vector<uint32_t>& tileStats, const HybridBlended* blended,
                              std::vector<DebugImage>& out) {
    out.push_back(
        {"lights_per_tile", passes::lightsPerTileHeatMap(t.grid, tileStatColumn(tileStats, 0)), true});
    if (blended)
        out.push_back({"lights_per_tile_transparent",
                       blended->heatMap(t.grid, tileStats, t.listOffsets), true});
    EdgeAndRoughMetal split = splitDebugImage(readbackColor(ctx, graph.image(t.debug)));
    out.push_back({"edge_mask", std::move(split.edge), true});
    out.push_back({"roughness_metallic", std::move(split.roughMetal), true});
}

} // namespace tp
