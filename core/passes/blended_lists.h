#pragma once
// Deferred's per-tile transparent light lists (blended scenes), in light assignment's
// compact layout (include/light_assign.h): one LaListHeader per tile, then each tile's run
// of light indices, the runs sized by a conservative CPU bound (core/lightassign), so the
// buffer grows with the lights the lists can hold, never with tiles x lights.
#include <cstdint>
#include <string>
#include <vector>

#include "core/lightassign/tile_grid.h"

namespace tp {

class SceneGpu;

struct TransparentListPlan {
    std::vector<uint32_t> offsets; // tileCount + 1: tile t's run is [offsets[t], offsets[t + 1])
    uint64_t slots = 0;            // light index slots (masks: bitmask words) over every tile
    uint64_t capacity = 0;         // slots the buffer holds: `slots`, with headroom (manyViews)
    bool masks = false;            // runs are bitmasks over the tiles' binned candidates
    uint64_t bytes() const;        // headers + capacity
};

// The lists' layout for the scene's current view and lights (capacity = slots), nothing
// refused: what planTransparentLists sizes the buffer from, and what a new view needs
// (HybridBlended::updateLists compares it with the planned capacity).
TransparentListPlan transparentListNeed(const la::TileGrid& grid, const SceneGpu& scene,
                                        bool masks, const std::vector<uint32_t>* localBound);

// Every light may enter a list (the tiled pass culls all of them against the transparent
// range): directional lights reach every tile, point/spot lights at most the tiles of
// la::conservativeTileBound. Throws RendererError when the buffer would exceed
// maxStorageBufferRange (`limit`). masks (--light-cull binned): a list is a subset of its
// tile's candidates (the directional lights and the lights whose conservative tile
// rectangle covers it: the same rectangles as the bound), so its run is a bitmask over them,
// ceil(candidates / 32) words (passes/tiled_lighting.h). localBound: that bound
// when the caller has binned the lights already (binned culling bins them once, on the CPU
// or the GPU); null: computed here. manyViews: capacity with headroom for later views
// (core/passes/tiled_lighting.h: viewCapacity), never more than every light in every tile or
// than `limit` allows.
TransparentListPlan planTransparentLists(const la::TileGrid& grid, const SceneGpu& scene,
                                         uint64_t limit, const std::string& deviceName, bool masks,
                                         const std::vector<uint32_t>* localBound,
                                         const std::string& owner, bool manyViews = false);

} // namespace tp
