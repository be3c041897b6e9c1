#version 460
#extension GL_GOOGLE_include_directive : require
// light_bin_sort for runs longer than TP_BIN_SHARED_SORT (a light over much of the screen):
// one bitonic step (block size k = TP_BIN_FIRST, distance j = TP_BIN_END) per dispatch, in
// place in the target buffer, in the formulation whose comparators all put the smaller value
// first (each merge starts by comparing i with its mirror in the block), over the run padded
// to a power of two with +inf. The padding is virtual: a comparator whose second element lies
// past the run compares with +inf and keeps the order, so it is skipped. Workgroups (chunk,
// tile x, tile y); each invocation takes at most TP_BIN_STEP_PAIRS pairs (lavapipe's loop limit).
#include "lightassign/bin_common.glsl"

layout(local_size_x = 64) in;

void main() {
    const uint t = gl_WorkGroupID.z * bin.grid.x + gl_WorkGroupID.y;
    const uint first = offsets[t], n = offsets[t + 1u] - first;
    const uint k = draw.TP_BIN_FIRST, j = draw.TP_BIN_END;
    if (n <= TP_BIN_SHARED_SORT || k > binSortSize(n)) return;
    const uint base = draw.TP_BIN_BASE + first, pairs = binSortSize(n) / 2u;
    const uint chunk = gl_WorkGroupID.x * 64u * TP_BIN_STEP_PAIRS;
    for (uint q = 0u; q < TP_BIN_STEP_PAIRS; ++q) {
        const uint p = chunk + q * 64u + gl_LocalInvocationIndex;
        if (p >= pairs) break;
        const uvec2 pair = binBitonicPair(p, k, j);
        const uint i = pair.x, other = pair.y;
        if (other >= n) continue;
        const uint a = target[base + i], b = target[base + other];
        if (a > b) {
            target[base + i] = b;
            target[base + other] = a;
        }
    }
}
