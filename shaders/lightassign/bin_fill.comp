#version 460
#extension GL_GOOGLE_include_directive : require
// light_bin_fill (step 5): every light into the runs of the tiles its rectangle covers, rows
// [TP_BIN_FIRST, TP_BIN_END) of tiles per dispatch (lavapipe's loop limit: at most
// TP_BIN_FILL_BUDGET tiles per light and dispatch). Each tile's count, counted down
// (atomic), is its cursor: the order inside a run depends on scheduling until the sort.
// The (light, tile) pairs of each 64 lights are spread evenly over the invocations of
// TP_BIN_SPLIT workgroups: the exclusive prefix sum of the rectangles' areas numbers the
// pairs, and pair i belongs to the last light whose sum is at most i. So a light over much of
// the screen is not one invocation's long chain of dependent atomics, and a light of one tile
// does not leave 63 invocations idle (an invocation per light, and a workgroup per light of
// over 32 tiles: 0.154 ms against 0.113 at 65,536 lights on the H200, docs/clustered.md).
#include "lightassign/bin_common.glsl"
#include "lightassign/bin_scan.glsl" // local_size_x = 64

layout(constant_id = TP_BIN_SPEC_FILL_RESERVE) const uint kReserveWords = 1u;
shared uint reserve[kReserveWords]; // include/light_binning.h: TP_BIN_FILL_RESERVE_WORDS
shared uint pairsBefore[64];
shared uvec4 spans[64]; // per light of the workgroup: first column, width, first row, light

// The workgroup's invocation whose light owns pair i: the last with pairsBefore <= i (a light
// without pairs shares its sum with the next, which wins). Six fixed steps, no loop
// (lavapipe counts loop iterations).
uint binPairOwner(uint i) {
    uint lo = 0u;
    lo += pairsBefore[lo + 32u] <= i ? 32u : 0u;
    lo += pairsBefore[lo + 16u] <= i ? 16u : 0u;
    lo += pairsBefore[lo + 8u] <= i ? 8u : 0u;
    lo += pairsBefore[lo + 4u] <= i ? 4u : 0u;
    lo += pairsBefore[lo + 2u] <= i ? 2u : 0u;
    lo += pairsBefore[lo + 1u] <= i ? 1u : 0u;
    return lo;
}

void main() {
    // TP_BIN_SPLIT workgroups share each 64 lights, pair i going to workgroup i / 64 modulo
    // the split: so that a few lights of many tiles still fill the GPU (at 1,024 lights, 16
    // workgroups of 64 would each walk thousands of pairs).
    const uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    const uint split = draw.TP_BIN_SPLIT, part = group % split;
    const uint lane = gl_LocalInvocationIndex, index = (group / split) * 64u + lane;
    // Written whole and read at an index from the inputs, so that no compiler can drop or
    // shrink it; each word by one lane (no race).
    for (uint w = lane; w < kReserveWords; w += 64u) reserve[w] = 0u;
    uint pairs = 0u;
    uvec4 span = uvec4(0u);
    if (index < bin.grid.w) {
        // Lights in descending order: a device that happens to run the workgroups in order (as
        // lavapipe nearly does) would leave the runs ascending and hide a broken sort from the
        // tests.
        const uint k = bin.grid.w - 1u - index;
        const ivec4 rect = binUnpackRect(rects[k]);
        const uint y0 = max(uint(rect.z), draw.TP_BIN_FIRST), y1 = min(uint(rect.w) + 1u, draw.TP_BIN_END);
        if (rect.x <= rect.y && y0 < y1) {
            span = uvec4(uint(rect.x), uint(rect.y - rect.x + 1), y0, locals[k]);
            pairs = span.y * (y1 - y0);
        }
    }
    uvec4 total;
    pairsBefore[lane] = binScanExclusive(uvec4(pairs, 0u, 0u, 0u), total).x;
    spans[lane] = span;
    barrier();
    const uint W = bin.grid.x;
    const uint first = part * 64u + lane + reserve[(lane + bin.grid.w) % kReserveWords]; // + 0
    for (uint i = first; i < total.x; i += 64u * split) {
        const uint owner = binPairOwner(i), j = i - pairsBefore[owner];
        const uvec4 s = spans[owner];
        binFillTile((s.z + j / s.y) * W + s.x + j % s.y, s.w);
    }
}
