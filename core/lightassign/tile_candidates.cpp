#include "core/lightassign/tile_candidates.h"

namespace tp::la {

std::vector<uint32_t> tileCandidates(const TileGrid& grid, const std::vector<TileRect>& rects,
                                     const std::vector<uint32_t>& local,
                                     const std::vector<uint32_t>& offsets) {
    std::vector<uint32_t> out(offsets.empty() ? 0 : offsets.back());
    // Each tile's cursor walks its run; lights are visited in ascending order, so every run
    // comes out ascending without a sort.
    std::vector<uint32_t> cursor(offsets.begin(), offsets.end() - (offsets.empty() ? 0 : 1));
    for (size_t k = 0; k < rects.size(); ++k) {
        const TileRect& r = rects[k];
        for (int y = r.y0; y <= r.y1; ++y)
            for (int x = r.x0; x <= r.x1; ++x) {
                uint32_t& c = cursor[size_t(y) * grid.tilesX + size_t(x)];
                out[c++] = local[k];
            }
    }
    return out;
}

} // namespace tp::la
