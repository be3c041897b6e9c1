#version 460
#extension GL_GOOGLE_include_directive : require
// light_binning, step 3: a workgroup per row of tiles. Along the row, the difference array's
// inclusive prefix sum R, with the direct counts folded in (below; into counts) and R's exclusive prefix sum E (into offsets), and R's
// sum over the row (into rowSums): what step 4 needs to finish counts and offsets going down
// the columns (bin_scan_columns.comp says how). The direct counts C (bin_rects.comp's small
// rectangles) are a difference array of their own, C(x, y) - C(x - 1, y) - C(x, y - 1) +
// C(x - 1, y - 1), whose prefix sum along the row is C(x, y) - C(x, y - 1): added to R here,
// they reach the counts and offsets with the rectangles' corners.
#include "lightassign/bin_common.glsl"
#include "lightassign/bin_scan.glsl"

void main() {
    const uint W = bin.grid.x, row = gl_WorkGroupID.x * W;
    const uvec2 share = binScanShare(W);
    uint sum = 0u;
    for (uint x = share.x; x < share.y; ++x) sum += counts[row + x];
    uvec4 total;
    uint r = binScanExclusive(uvec4(sum, 0u, 0u, 0u), total).x, rSum = 0u;
    const uint direct = bin.grid.z;
    for (uint x = share.x; x < share.y; ++x) {
        r += counts[row + x];
        const uint above = row == 0u ? 0u : counts[direct + row - W + x];
        const uint rWithDirect = r + counts[direct + row + x] - above; // modulo 2^32, as the corners
        counts[row + x] = rWithDirect;
        rSum += rWithDirect;
    }
    uint e = binScanExclusive(uvec4(rSum, 0u, 0u, 0u), total).x;
    for (uint x = share.x; x < share.y; ++x) {
        offsets[row + x] = e;
        e += counts[row + x];
    }
    if (gl_LocalInvocationIndex == 0u) rowSums[gl_WorkGroupID.x] = total.x;
}
