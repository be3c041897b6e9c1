#pragma once
// Binned culling's candidate lists: for every tile, the local lights whose conservative tile
// rectangle (tile_bound.h) covers it, in ascending light order. The GPU then tests only a
// tile's candidates instead of every light, so culling costs
// lights * (tilesX + tilesY) on the CPU (the rectangles, per view: when planned and when the
// camera or the lights move) plus the candidates on the GPU, never tiles x lights.
// The candidates of a tile are a superset of what the GPU keeps (its test is a subset of the
// rectangle's volume), so the kept lists are exactly brute-force culling's, in the same order.
#include <cstdint>
#include <vector>

#include "core/lightassign/tile_bound.h"
#include "core/lightassign/tile_grid.h"

namespace tp::la {

// Tile t's candidates are out[offsets[t] .. offsets[t + 1]): the light indices local[k] of
// every rectangle rects[k] that covers t, ascending in k. `offsets` is the compact layout of
// countTileRects(grid, rects) (makeCompactLayout with no extra slots).
std::vector<uint32_t> tileCandidates(const TileGrid& grid, const std::vector<TileRect>& rects,
                                     const std::vector<uint32_t>& local,
                                     const std::vector<uint32_t>& offsets);

} // namespace tp::la
