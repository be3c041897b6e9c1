#pragma once
// Forward+ statistics and debug images from the read-back tile lists.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/image/image.h"
#include "core/lightassign/tile_grid.h"
#include "forwardplus/forwardplus_shared.h"

namespace tp::fp {

struct TileListSummary {
    double mean = 0.0;     // lights per tile (stored), over every tile
    uint32_t max = 0;      // lights in the fullest tile (stored)
    uint32_t skyTiles = 0; // tiles with no geometry
    double tested = 0.0;   // light-vs-tile tests made (sky tiles test nothing for the opaque list)
    double passed = 0.0;   // tests passed (stored + dropped)
    double stored = 0.0;
    double dropped = 0.0;
};

// `candidates`: per tile, the lights it tests (binned culling); empty: every tile tests all
// `localLights`. `testsSky`: the list is culled on tiles without geometry too (the
// transparent list, and clustered's span list when blended surfaces exist).
TileListSummary summarize(const std::vector<gpu::FpTileLists>& tiles, uint32_t list, bool testsSky,
                          size_t localLights, const std::vector<uint32_t>& candidates = {});

// Clustered: lights per (tile, slice) cluster from the read-back bitmasks, over the
// clusters of tiles with geometry (a sky tile's clusters only serve blended surfaces).
struct ClusterSummary {
    double mean = 0.0; // lights per cluster
    uint32_t max = 0;
    double bits = 0.0; // set bits in all masks
};
ClusterSummary summarizeClusters(const std::vector<gpu::FpTileLists>& tiles,
                                 const std::vector<uint32_t>& maskOffsets,
                                 const std::vector<uint32_t>& masks, uint32_t slices);
// Clustered blended scenes: lights per front cluster (the first `frontSlices` slices, which a
// blended fragment nearer than its tile's opaque range looks up), over the tiles whose front
// slices start at a blended fragment (frontNear < sliceNear).
ClusterSummary summarizeFrontClusters(const std::vector<gpu::FpTileLists>& tiles,
                                      const std::vector<uint32_t>& maskOffsets,
                                      const std::vector<uint32_t>& masks, uint32_t slices,
                                      uint32_t frontSlices);

// Lights per tile (list 0 opaque, 1 transparent) on light assignment's one heat-map scale
// (core/passes/debug_views.h); tiles that dropped lights (overflow of the "fixed" layout)
// are outlined.
ImageRGBA lightsPerTileHeatMap(const la::TileGrid& grid, const std::vector<gpu::FpTileLists>& tiles,
                               uint32_t list);

// passes::tileDepthBoundsImage of the lists' depth ranges.
ImageRGBA tileDepthBoundsImage(const la::TileGrid& grid, const std::vector<gpu::FpTileLists>& tiles,
                               const glm::mat4& invProj);

} // namespace tp::fp
