#pragma once
// Forward+'s counters of the read-back light lists (lights per tile, per cluster, tested,
// kept, stored, dropped), for RendererStats: what the renderer reports once the frames ran.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/passes/blended_bounds.h"
#include "forwardplus/forwardplus_shared.h"

namespace tp::fp {

struct ListCounterInput {
    const std::vector<gpu::FpTileLists>& tiles; // read back: the tile records
    const std::vector<la::TileBlendedBounds>&
        blended;                              // read back (blended scenes): each tile's bounds
    const std::vector<uint32_t>& tested;      // binned: each tile's candidates; empty: every light
    const std::vector<uint32_t>& maskOffsets; // clustered: each tile's first slice-row word
    const std::vector<uint32_t>& maskBits;    // clustered: read back, the slice rows
    size_t localLights = 0;
    uint32_t slices = 0;   // clustered: slices per tile
    bool twoLists = false; // tiled with blended surfaces: the transparent list
    bool clustered = false;
    bool blendPass = false; // the scene draws blended surfaces
    bool linked = false;    // the linked layout: node counts
    uint32_t nodesUsed = 0;
    uint64_t poolNodes = 0;
};

void addListCounters(std::vector<std::pair<std::string, double>>& counters,
                     const ListCounterInput& in);

} // namespace tp::fp
