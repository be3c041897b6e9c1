#include "core/lightassign/corner_atomics.h"

#include <algorithm>

namespace tp::la {

uint64_t binCornerAtomics(const std::vector<TileRect>& rects, const TileGrid& grid) {
    uint64_t atomics = 0;
    for (const TileRect& r : rects) {
        if (r.empty()) continue;
        const bool right = uint32_t(r.x1) + 1 < grid.tilesX, below = uint32_t(r.y1) + 1 < grid.tilesY;
        const uint64_t corners = 1 + uint64_t(right) + uint64_t(below) + uint64_t(right && below);
        const uint64_t area = uint64_t(r.x1 - r.x0 + 1) * uint64_t(r.y1 - r.y0 + 1);
        atomics += std::min(area, corners);
    }
    return atomics;
}

} // namespace tp::la
