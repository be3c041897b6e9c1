#pragma once
// The debug views of the pass library: the lights-per-tile heat map and the tile depth bounds
// of every tiled pipeline, one colour scale and one legend each, so Forward+'s and deferred's
// (and any later pipeline's) maps of the same scene read alike.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/image/image.h"
#include "core/lightassign/tile_grid.h"

namespace tp::passes {

using la::TileGrid;

// The top of the scale: the largest count, at least 1 (an all-empty map stays black).
uint32_t heatMapScaleMax(const std::vector<uint32_t>& counts);

// Lights per tile (counts[tile], row-major) on the shared heat-map scale of
// core/image/difference.h (0 to heatMapScaleMax, legend strip under the image). Tiles whose
// `dropped` entry is non-zero are outlined in bright green: a list that lost lights is
// shown, never hidden. `dropped` may be empty (nothing can drop).
ImageRGBA lightsPerTileHeatMap(const TileGrid& grid, const std::vector<uint32_t>& counts,
                               const std::vector<uint32_t>& dropped = {});

// A tile's depth range, reverse-Z device depth (nearDepth <= 0: no geometry in the tile).
struct TileDepthRange {
    float nearDepth = 0.0f, farDepth = 0.0f;
};

// Tile depth bounds as view distance, nearest | farthest side by side on one scale (0 to
// the farthest bound); tiles without geometry are magenta (the scale's "not a number").
ImageRGBA tileDepthBoundsImage(const TileGrid& grid, const std::vector<TileDepthRange>& tiles,
                               const glm::mat4& invProj);

} // namespace tp::passes
