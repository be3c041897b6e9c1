#include "core/lightassign/tile_grid.h"

namespace tp::la {

TileGrid makeTileGrid(uint32_t width, uint32_t height, uint32_t tileSize) {
    TileGrid g;
    g.width = width;
    g.height = height;
    g.tileSize = tileSize;
    g.tilesX = (width + tileSize - 1) / tileSize;
    g.tilesY = (height + tileSize - 1) / tileSize;
    return g;
}

} // namespace tp::la
