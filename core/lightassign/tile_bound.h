#pragma once
// A conservative per-tile upper bound on the number of local lights the GPU can keep in a
// tile's list, used to size compact light lists so that they cannot overflow.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/lightassign/tile_grid.h"
#include "include/shared.h"

namespace tp::la {

// The tiles a light may touch: columns [x0, x1] x rows [y0, y1] (empty when x0 > x1).
struct TileRect {
    int x0 = 0, x1 = -1, y0 = 0, y1 = -1;
    bool empty() const { return x0 > x1 || y0 > y1; }
};

// The slab planes of the grid's columns and rows (unit inward normal, offset), laid out as
// the GPU binning reads them (include/light_binning.h: BinInputs.slabs): every column's
// "ndc >= lower edge" plane, every column's "<= upper edge" plane, then the rows' likewise.
std::vector<glm::vec4> binSlabPlanes(const TileGrid& grid, const glm::mat4& proj);

// Per local light (in `local` order), the rectangle of tiles whose depth-unbounded frustum
// its padded sphere meets; conservativeTileBound counts these rectangles per tile. In float,
// with the operations of include/light_binning.h: the GPU binning computes the same rectangles.
std::vector<TileRect> conservativeTileRects(const TileGrid& grid, const glm::mat4& view,
                                            const glm::mat4& proj,
                                            const std::vector<gpu::LightGpu>& lights,
                                            const std::vector<uint32_t>& local);

// How many of `rects` cover each tile.
std::vector<uint32_t> countTileRects(const TileGrid& grid, const std::vector<TileRect>& rects);

// For every tile, an upper bound on the local lights whose sphere meets the tile's
// depth-unbounded frustum (the side planes x_ndc, y_ndc = tile edges). The GPU tests a
// subset of that volume (its frustum is also bounded in depth, spot lights also by their
// cone, optionally by the frustum's box) with a much smaller padding, so its count can
// never exceed this bound - for either depth range (opaque or transparent).
// Computed per light as a column range times a row range: O(log(tilesX) + log(tilesY)) per
// light wholly in front of the eye (bisection), O(tilesX + tilesY) per light reaching behind it.
// view/proj/lights must be what the GPU tests (the uploaded, camera-relative ones).
std::vector<uint32_t> conservativeTileBound(const TileGrid& grid, const glm::mat4& view,
                                            const glm::mat4& proj,
                                            const std::vector<gpu::LightGpu>& lights,
                                            const std::vector<uint32_t>& local);

} // namespace tp::la
