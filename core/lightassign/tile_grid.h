#pragma once
// The screen-space tile grid both tiled pipelines (Forward+, tiled deferred) assign lights
// to: tiles of tileSize x tileSize pixels from the top-left corner, the last column and row
// partial when the viewport is not a multiple of the tile size. The GLSL side computes the
// same index (shaders/include/light_assign.glsl: laTileIndex).
#include <cstdint>

namespace tp::la {

struct TileGrid {
    uint32_t width = 0, height = 0; // viewport in pixels
    uint32_t tileSize = 16;
    uint32_t tilesX = 0, tilesY = 0;
    uint32_t count() const { return tilesX * tilesY; }
    // Row-major index of the tile holding pixel (x, y); the pixel must lie in the viewport.
    uint32_t tileOf(uint32_t x, uint32_t y) const { return (y / tileSize) * tilesX + x / tileSize; }
};

TileGrid makeTileGrid(uint32_t width, uint32_t height, uint32_t tileSize);

} // namespace tp::la
