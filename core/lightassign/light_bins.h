#pragma once
// Light binning on the CPU, shared by the pipelines that cull per tile (Forward+, tiled
// deferred): every local light's conservative tile rectangle (tile_bound.h), counted per
// tile (the bound), laid out compactly (compact_layout.h) and, for binned culling, each
// tile's candidates (tile_candidates.h). When a renderer is planned, and again for every new
// view of a renderer that follows the camera and the lights (Renderer::updateView). Each
// pipeline keeps its own size limits and error messages.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/lightassign/tile_grid.h"
#include "include/shared.h"

namespace tp::la {

struct LightBins {
    std::vector<uint32_t> bound; // per tile: how many local lights' rectangles cover it
    std::vector<uint32_t>
        offsets;        // compact layout of `bound`: tileCount + 1 entries (clamped to 32 bits)
    uint64_t slots = 0; // offsets' total, unclamped: callers refuse what they cannot address
    std::vector<uint32_t>
        candidates;        // tile t's are [offsets[t], offsets[t + 1]); empty unless asked for
    uint32_t maxBound = 0; // the largest bound of any tile
};

// view/proj/lights must be what the GPU tests (the uploaded, camera-relative ones); `local`
// indexes `lights`. Candidates are built only when asked for and when `slots` fits in 32
// bits (the offsets address them; a caller refuses larger bins before using them).
LightBins binLights(const TileGrid& grid, const glm::mat4& view, const glm::mat4& proj,
                    const std::vector<gpu::LightGpu>& lights, const std::vector<uint32_t>& local,
                    bool withCandidates);

} // namespace tp::la
