#version 460
#extension GL_GOOGLE_include_directive : require
// light_bin_sort for runs longer than TP_BIN_SHARED_SORT (a light over much of the screen):
// the bitonic steps whose distance j is below the block (TP_BIN_SHARED_SORT lights), which
// never leave a block, done in shared memory in one dispatch instead of one dispatch per
// step. A workgroup per (block, tile x, tile y); block sizes k = TP_BIN_FIRST..TP_BIN_END
// (powers of two), each from distance min(k / 2, block / 2) down to 1. With k from 2 to the
// block, it sorts every block ascending (the first stages); with one k past the block, it
// finishes that merge after bin_sort_step.comp's steps at j >= block. The comparators are
// bin_sort_step.comp's (the smaller value first; a merge starts with the mirror), the
// padding past the run +inf: blocks that hold no light of the run are skipped.
#include "lightassign/bin_common.glsl"

layout(local_size_x = 64) in;

shared uint block[TP_BIN_SHARED_SORT];

void main() {
    const uint t = gl_WorkGroupID.z * bin.grid.x + gl_WorkGroupID.y;
    const uint first = offsets[t], n = offsets[t + 1u] - first, lane = gl_LocalInvocationIndex;
    const uint kFrom = draw.TP_BIN_FIRST, kTo = draw.TP_BIN_END, start = gl_WorkGroupID.x * TP_BIN_SHARED_SORT;
    // Uniform over the workgroup: short runs (bin_sort.comp), runs already sorted at this k,
    // blocks wholly past the run.
    if (n <= TP_BIN_SHARED_SORT || kFrom > binSortSize(n) || start >= n) return;
    const uint base = draw.TP_BIN_BASE + first + start, count = min(TP_BIN_SHARED_SORT, n - start);
    for (uint i = lane; i < TP_BIN_SHARED_SORT; i += 64u) block[i] = i < count ? target[base + i] : 0xffffffffu;
    barrier();
    for (uint k = kFrom; k <= kTo; k <<= 1u)
        for (uint j = min(k >> 1u, TP_BIN_SHARED_SORT / 2u); j > 0u; j >>= 1u) {
            for (uint p = lane; p < TP_BIN_SHARED_SORT / 2u; p += 64u) {
                const uvec2 pair = binBitonicPair(p, k, j);
                // The mirror only while k fits the block (a merge's first step); past it, that
                // step was bin_sort_step.comp's. Indices in the block: start is a multiple of k then.
                const uint i = pair.x, other = pair.y;
                const uint a = block[i], b = block[other];
                if (a > b) {
                    block[i] = b;
                    block[other] = a;
                }
            }
            barrier();
        }
    for (uint i = lane; i < count; i += 64u) target[base + i] = block[i];
}
