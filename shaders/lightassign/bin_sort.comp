#version 460
#extension GL_GOOGLE_include_directive : require
// light_bin_sort (step 6): each tile's run sorted ascending, a workgroup per tile, in shared
// memory (runs of 2 to TP_BIN_SHARED_SORT lights; longer ones: bin_sort_local.comp and bin_sort_step.comp). Runs up
// to TP_BIN_RANK_SORT lights by rank; longer ones by a bitonic
// sort over the run padded to a power of two with +inf (0xffffffff), in the formulation
// whose comparators all put the smaller value first (each merge starts by comparing i with
// its mirror in the block): so the padding stays at the end and the first n are the run,
// exactly the CPU's ascending run.
#include "lightassign/bin_common.glsl"

layout(local_size_x_id = TP_BIN_SPEC_SORT_GROUP) in; // TP_BIN_SORT_GROUP_GPU or _CPU
#define TP_BIN_SORT_GROUP gl_WorkGroupSize.x

shared uint run[TP_BIN_SHARED_SORT];

void main() {
    const uint t = gl_WorkGroupID.y * bin.grid.x + gl_WorkGroupID.x;
    const uint first = offsets[t], n = offsets[t + 1u] - first, lane = gl_LocalInvocationIndex;
    if (n < 2u || n > TP_BIN_SHARED_SORT) return; // uniform over the workgroup
    const uint base = draw.TP_BIN_BASE + first, size = binSortSize(n);
    for (uint i = lane; i < size; i += TP_BIN_SORT_GROUP) run[i] = i < n ? target[base + i] : 0xffffffffu;
    barrier();
    if (n <= TP_BIN_RANK_SORT) {
        // Short runs: each light goes to its rank (how many of the run are smaller; a run holds
        // a light once). n^2 / 64 compares per invocation but one barrier, where the bitonic
        // sort takes log2(size)(log2(size) + 1) / 2: barriers are what lavapipe pays most for.
        for (uint i = lane; i < n; i += TP_BIN_SORT_GROUP) {
            const uint v = run[i];
            uint rank = 0u;
            for (uint j = 0u; j < n; ++j) rank += run[j] < v ? 1u : 0u;
            target[base + rank] = v;
        }
        return;
    }
    for (uint k = 2u; k <= size; k <<= 1u)
        for (uint j = k >> 1u; j > 0u; j >>= 1u) {
            for (uint p = lane; p < size / 2u; p += TP_BIN_SORT_GROUP) {
                const uvec2 pair = binBitonicPair(p, k, j);
                const uint i = pair.x, other = pair.y;
                // other > i: past the run, +inf, which keeps the order (as in bin_sort_step).
                if (other >= n) continue;
                const uint a = run[i], b = run[other];
                if (a > b) {
                    run[i] = b;
                    run[other] = a;
                }
            }
            barrier();
        }
    for (uint i = lane; i < n; i += TP_BIN_SORT_GROUP) target[base + i] = run[i];
}
