#version 460
#extension GL_GOOGLE_include_directive : require
// light_binning, step 4: a workgroup per column of tiles; with step 3's R (row prefix sums of
// the difference array, plus C(x, y) - C(x, y - 1) of the direct counts), E (row prefix sums of R, exclusive) and rowSums (R's sum per row):
//   counts(x, y)  = sum over y' <= y of R(x, y')      how many rectangles cover the tile
//   rowTotal(y)   = sum over y' <= y of rowSums(y')    the counts' sum over row y
//   offsets(x, y) = sum over y' < y of rowTotal(y')   the tiles of the rows above
//                 + sum over y' <= y of E(x, y')      the tiles left of it in its row
// so the counts and their row-major exclusive prefix sum (the compact layout) come out of
// one pass down the columns: two dispatches, where a scan along the rows, one down the
// columns and a prefix sum over all tiles took three, each a serial loop.
#include "lightassign/bin_common.glsl"
#include "lightassign/bin_scan.glsl"

void main() {
    const uint W = bin.grid.x, H = bin.grid.y, x = gl_WorkGroupID.x;
    const uvec2 share = binScanShare(H);
    uvec4 sum = uvec4(0u); // R, E and rowSums over this invocation's rows
    for (uint y = share.x; y < share.y; ++y) sum += uvec4(counts[y * W + x], offsets[y * W + x], rowSums[y], 0u);
    uvec4 total;
    const uvec4 before = binScanExclusive(sum, total);
    uint rowTotal = before.z, aboveSum = 0u; // the rows' totals, and their sum over this share
    for (uint y = share.x; y < share.y; ++y) {
        rowTotal += rowSums[y];
        aboveSum += rowTotal;
    }
    uvec4 slots;
    uint above = binScanExclusive(uvec4(aboveSum, 0u, 0u, 0u), slots).x; // the rows above this share
    uint count = before.x, left = before.y, longest = 0u;
    rowTotal = before.z;
    // The frame: each offset clamped to the room (published for the consumers, which read
    // their runs as offset differences), so a view past it cuts its runs instead of writing
    // past them; overflowed() reads the needs and has the view planned again.
    const bool publish = draw.TP_BIN_PUBLISH != 0u;
    const uint room = publish ? draw.TP_BIN_ROOM : 0xffffffffu;
    for (uint y = share.x; y < share.y; ++y) {
        const uint t = y * W + x;
        count += counts[t];
        left += offsets[t];
        counts[t] = count;
        longest = max(longest, count);
        const uint offset = min(above + left, room);
        offsets[t] = offset;
        if (publish) target[draw.TP_BIN_OFFSETS_WORD + t] = offset;
        rowTotal += rowSums[y];
        above += rowTotal;
    }
    atomicMax(offsets[bin.grid.z + 1u + TP_BIN_NEED_RUN], longest);
    if (x == 0u && gl_LocalInvocationIndex == 0u) {
        offsets[bin.grid.z] = min(slots.x, room);
        offsets[bin.grid.z + 1u + TP_BIN_NEED_SLOTS] = slots.x;
        if (publish) target[draw.TP_BIN_OFFSETS_WORD + bin.grid.z] = min(slots.x, room);
    }
}
