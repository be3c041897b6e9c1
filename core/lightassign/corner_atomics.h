#pragma once
// The GPU binning's atomics on its counts (core/passes/light_binning.h, step 2), counted from
// the rectangles: the light_binning pass's global_atomics, placed against the atomics
// ceiling. One function for the pass's readback and the tests' CPU rectangles.
#include <cstdint>
#include <vector>

#include "core/lightassign/tile_bound.h"
#include "core/lightassign/tile_grid.h"

namespace tp::la {

// bin_rects.comp: a rectangle adds at its first tile and, where they fall inside the grid, at
// the tiles past its last column, past its last row, and past both (the difference array);
// one of fewer tiles than those corners adds at each of its tiles instead (the direct counts).
uint64_t binCornerAtomics(const std::vector<TileRect>& rects, const TileGrid& grid);

} // namespace tp::la
