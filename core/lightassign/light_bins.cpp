#include "core/lightassign/light_bins.h"

#include <algorithm>

#include "core/lightassign/compact_layout.h"
#include "core/lightassign/tile_bound.h"
#include "core/lightassign/tile_candidates.h"

namespace tp::la {

LightBins binLights(const TileGrid& grid, const glm::mat4& view, const glm::mat4& proj,
                    const std::vector<gpu::LightGpu>& lights, const std::vector<uint32_t>& local,
                    bool withCandidates) {
    LightBins bins;
    std::vector<TileRect> rects = conservativeTileRects(grid, view, proj, lights, local);
    bins.bound = countTileRects(grid, rects);
    CompactLayout compact = makeCompactLayout(bins.bound);
    bins.offsets = std::move(compact.offsets);
    bins.slots = compact.slots;
    if (!bins.bound.empty())
        bins.maxBound = *std::max_element(bins.bound.begin(), bins.bound.end());
    // Clamped offsets would send tileCandidates past its output: such bins are refused anyway.
    if (withCandidates && bins.slots <= 0xffffffffull)
        bins.candidates = tileCandidates(grid, rects, local, bins.offsets);
    return bins;
}

} // namespace tp::la
