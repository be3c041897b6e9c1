#include "core/lightassign/compact_layout.h"

#include <algorithm>

namespace tp::la {

CompactLayout makeCompactLayout(const std::vector<uint32_t>& bound, uint32_t perTileExtra) {
    CompactLayout c;
    c.offsets.assign(bound.size() + 1, 0);
    uint64_t total = 0;
    for (size_t t = 0; t < bound.size(); ++t) {
        c.offsets[t] = uint32_t(std::min<uint64_t>(total, 0xffffffffu));
        total += uint64_t(bound[t]) + perTileExtra;
    }
    c.offsets[bound.size()] = uint32_t(std::min<uint64_t>(total, 0xffffffffu));
    c.slots = total;
    return c;
}

} // namespace tp::la
