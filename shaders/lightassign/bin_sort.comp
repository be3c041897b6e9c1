#version 460
#extension GL_GOOGLE_include_directive : require
// light_bin_sort (step 6): each tile's run sorted ascending, a workgroup per tile, runs of 2
// to kSharedRun lights (the frame's longest, include/light_binning.h; longer ones than
// TP_BIN_SHARED_SORT: bin_sort_local.comp and bin_sort_step.comp).
// A run holds each light once, so its order needs no compare network:
// - up to TP_BIN_RANK_SORT lights, each light goes to its rank (how many of the run are
//   smaller): one barrier, n compares a light;
// - longer runs by buckets: kBuckets equal buckets over the range of every local light's
//   index, counted, scanned and filled in shared memory, then each light to its bucket's
//   start plus its rank among its bucket's lights: six barriers and a bucket's size in
//   compares a light, where the bitonic network takes 45 to 78 barriers and as many
//   compare-exchanges (H200: 0.171 -> 0.10 ms at 65,536 lights, docs/clustered.md);
// - a run with a bucket of more than TP_BIN_BUCKET_MOST lights (a tile's light indices
//   crowded in a part of the range, as a scene whose lights are listed in order of place
//   may give) by the bitonic network after all, over the run padded to a power of two with
//   +inf (0xffffffff), in the formulation whose comparators all put the smaller value first
//   (each merge starts by comparing i with its mirror in the block): so the padding stays at
//   the end and the first n are the run, exactly the CPU's ascending run.
#include "lightassign/bin_common.glsl"

layout(local_size_x_id = TP_BIN_SPEC_SORT_GROUP) in; // TP_BIN_SORT_GROUP_GPU or _CPU
#define TP_BIN_SORT_GROUP gl_WorkGroupSize.x
layout(constant_id = TP_BIN_SPEC_SORT_BUCKETS) const uint kBuckets = TP_BIN_SORT_BUCKETS;

layout(constant_id = TP_BIN_SPEC_SORT_SHARED) const uint kSharedRun = TP_BIN_SHARED_SORT;
shared uint run[kSharedRun];
shared uint bucketStart[kBuckets + 1u]; // exclusive prefix sum of the bucket sizes, then n
shared uint bucketFill[kBuckets];       // each bucket's size, then its cursor
shared uint laneSum[TP_BIN_SORT_GROUP_GPU];
shared uint groupSum[TP_BIN_SORT_GROUP_GPU / 16u];
shared uint crowded; // 1: a bucket holds more than TP_BIN_BUCKET_MOST lights

// Exclusive prefix sum of `v` over the workgroup, without subgroup operations (their width
// differs between devices) nor atomics on one word: the first G / 16 lanes each scan 16
// lanes' values in turn, then every lane adds the totals of the groups of 16 before its own.
// Two barriers.
uint scanLanes(uint v) {
    const uint lane = gl_LocalInvocationIndex;
    laneSum[lane] = v;
    barrier();
    if (lane < TP_BIN_SORT_GROUP / 16u) {
        uint acc = 0u;
        for (uint i = lane * 16u; i < lane * 16u + 16u; ++i) {
            const uint s = laneSum[i];
            laneSum[i] = acc;
            acc += s;
        }
        groupSum[lane] = acc;
    }
    barrier();
    uint before = laneSum[lane];
    for (uint g = 0u; g < lane / 16u; ++g) before += groupSum[g];
    return before;
}

// Bucket starts: an exclusive prefix sum over the bucket sizes, each lane summing its share
// of the buckets; the sizes become the fill's cursors.
void scanBuckets(uint n) {
    const uint lane = gl_LocalInvocationIndex, per = (kBuckets + TP_BIN_SORT_GROUP - 1u) / TP_BIN_SORT_GROUP;
    const uint first = min(lane * per, kBuckets), end = min(first + per, kBuckets);
    uint sum = 0u;
    for (uint b = first; b < end; ++b) sum += bucketFill[b];
    uint before = scanLanes(sum);
    for (uint b = first; b < end; ++b) {
        const uint size = bucketFill[b];
        bucketStart[b] = before;
        bucketFill[b] = before; // the cursor of the bucket fill
        before += size;
    }
    if (lane == 0u) bucketStart[kBuckets] = n;
}

// The run (loaded by every lane) ascending in place in shared memory: the bitonic network over
// it padded with +inf, virtually: a pair whose partner lies past the run is skipped.
void bitonicSort(uint n, uint lane) {
    const uint size = binSortSize(n);
    barrier();
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
}

void main() {
    const uint t = gl_WorkGroupID.y * bin.grid.x + gl_WorkGroupID.x;
    const uint first = offsets[t], n = offsets[t + 1u] - first, lane = gl_LocalInvocationIndex;
    if (n < 2u || n > kSharedRun) return; // uniform over the workgroup
    const uint base = draw.TP_BIN_BASE + first;
    if (n <= TP_BIN_RANK_SORT) {
        for (uint i = lane; i < n; i += TP_BIN_SORT_GROUP) run[i] = target[base + i];
        barrier();
        for (uint i = lane; i < n; i += TP_BIN_SORT_GROUP) {
            const uint v = run[i];
            uint rank = 0u;
            for (uint j = 0u; j < n; ++j) rank += run[j] < v ? 1u : 0u;
            target[base + rank] = v;
        }
        return;
    }
    // The buckets span every local light's index (ascending in `locals`): the run's own
    // range, found with two more barriers, was slower on the H200 (0.128 against 0.108 ms
    // at 65,536 lights).
    const uint lo = locals[0], bits = uint(findMSB(locals[bin.grid.w - 1u] - lo) + 1);
    const uint shift = uint(max(0, int(bits) - findMSB(kBuckets)));
    for (uint b = lane; b < kBuckets; b += TP_BIN_SORT_GROUP) bucketFill[b] = 0u;
    if (lane == 0u) crowded = 0u;
    barrier();
    for (uint i = lane; i < n; i += TP_BIN_SORT_GROUP)
        if (atomicAdd(bucketFill[(target[base + i] - lo) >> shift], 1u) >= TP_BIN_BUCKET_MOST)
            atomicOr(crowded, 1u); // only where a bucket is crowded: the fallback's cost
    barrier();
    if (crowded != 0u) { // uniform: read after the barrier
        if (lane == 0u) atomicAdd(offsets[bin.grid.z + 1u + TP_BIN_NEED_FALLBACKS], 1u); // a statistic
        for (uint i = lane; i < n; i += TP_BIN_SORT_GROUP) run[i] = target[base + i];
        bitonicSort(n, lane);
        for (uint i = lane; i < n; i += TP_BIN_SORT_GROUP) target[base + i] = run[i];
        return;
    }
    scanBuckets(n);
    barrier();
    // Each light into its bucket (in any order), then to its bucket's start plus its rank there.
    for (uint i = lane; i < n; i += TP_BIN_SORT_GROUP) {
        const uint v = target[base + i];
        run[atomicAdd(bucketFill[(v - lo) >> shift], 1u)] = v;
    }
    barrier();
    for (uint i = lane; i < n; i += TP_BIN_SORT_GROUP) {
        const uint v = run[i], b = (v - lo) >> shift, from = bucketStart[b], to = bucketStart[b + 1u];
        uint rank = 0u;
        for (uint j = from; j < to; ++j) rank += run[j] < v ? 1u : 0u;
        target[base + from + rank] = v;
    }
}
