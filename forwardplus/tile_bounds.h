#pragma once
// CPU side of the Forward+ tiling: the tile grid, the light classes (directional lights are
// shaded everywhere, point/spot lights are culled) and a conservative per-tile upper bound
// on the number of lights the GPU can keep in a tile, used to size the "compact" and
// "linked" light lists so that they cannot overflow.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "include/shared.h"

namespace tp::fp {

struct TileGrid {
    uint32_t width = 0, height = 0; // viewport in pixels
    uint32_t tileSize = 16;
    uint32_t tilesX = 0, tilesY = 0;
    uint32_t count() const { return tilesX * tilesY; }
};

TileGrid makeTileGrid(uint32_t width, uint32_t height, uint32_t tileSize);

struct LightClasses {
    std::vector<uint32_t> directional; // indices into the light array
    std::vector<uint32_t> local;       // point and spot lights, ascending
};

LightClasses classifyLights(const std::vector<gpu::LightGpu>& lights);

// For every tile, an upper bound on the local lights whose sphere meets the tile's
// depth-unbounded frustum (the side planes x_ndc, y_ndc = tile edges). The GPU tests a
// subset of that volume (its frustum is also bounded in depth, spot lights also by their
// cone) with a much smaller padding, so its count can never exceed this bound.
// Computed per light as a column range times a row range: O(lights * (tilesX + tilesY)).
std::vector<uint32_t> conservativeTileBound(const TileGrid& grid, const glm::mat4& view,
                                            const glm::mat4& proj,
                                            const std::vector<gpu::LightGpu>& lights,
                                            const std::vector<uint32_t>& local);

} // namespace tp::fp
