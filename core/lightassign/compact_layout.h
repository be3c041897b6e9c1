#pragma once
// The compact light-list layout: every tile's list is a run of slots in one index buffer,
// [offsets[t], offsets[t + 1]), sized by a per-tile upper bound (conservativeTileBound plus
// the lights a list holds unculled). Its size grows with the lights the lists can hold,
// never with tiles x lights. A list longer than its run is cut and the rest counted
// (never silent); with a conservative bound that cannot happen.
#include <cstdint>
#include <vector>

namespace tp::la {

struct CompactLayout {
    std::vector<uint32_t> offsets; // tileCount + 1 entries: exclusive prefix sum of the bounds
    uint64_t slots = 0;            // total slots of one list kind (offsets.back(), unclamped)
};

// offsets[t] = sum over tiles before t of (bound[t'] + perTileExtra), clamped to
// 0xffffffff (the caller refuses a layout whose `slots` does not fit in 32 bits).
CompactLayout makeCompactLayout(const std::vector<uint32_t>& bound, uint32_t perTileExtra = 0);

} // namespace tp::la
