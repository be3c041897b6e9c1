#pragma once
// The lights-per-tile heat map of every tiled pipeline: one colour scale and one legend, so
// Forward+'s and deferred's maps of the same scene read alike.
#include <cstdint>
#include <vector>

#include "core/image/image.h"
#include "core/lightassign/tile_grid.h"

namespace tp::la {

// The top of the scale: the largest count, at least 1 (an all-empty map stays black).
uint32_t heatMapScaleMax(const std::vector<uint32_t>& counts);

// Lights per tile (counts[tile], row-major) on the shared heat-map scale of
// core/image/difference.h (0 to heatMapScaleMax, legend strip under the image). Tiles whose
// `dropped` entry is non-zero are outlined in bright green: a list that lost lights is
// shown, never hidden. `dropped` may be empty (nothing can drop).
ImageRGBA lightsPerTileHeatMap(const TileGrid& grid, const std::vector<uint32_t>& counts,
                               const std::vector<uint32_t>& dropped = {});

} // namespace tp::la
