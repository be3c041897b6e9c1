#version 460
#extension GL_GOOGLE_include_directive : require
// light_binning, step 3: a workgroup per row of tiles. Along the row, the difference array's
// inclusive prefix sum R (into counts) and R's exclusive prefix sum E (into offsets), and R's
// sum over the row (into rowSums): what step 4 needs to finish counts and offsets going down
// the columns (bin_scan_columns.comp says how).
#include "lightassign/bin_common.glsl"
#include "lightassign/bin_scan.glsl"

void main() {
    const uint W = bin.grid.x, row = gl_WorkGroupID.x * W;
    const uvec2 share = binScanShare(W);
    uint sum = 0u;
    for (uint x = share.x; x < share.y; ++x) sum += counts[row + x];
    uvec4 total;
    uint r = binScanExclusive(uvec4(sum, 0u, 0u, 0u), total).x, rSum = 0u;
    for (uint x = share.x; x < share.y; ++x) {
        r += counts[row + x];
        counts[row + x] = r;
        rSum += r;
    }
    uint e = binScanExclusive(uvec4(rSum, 0u, 0u, 0u), total).x;
    for (uint x = share.x; x < share.y; ++x) {
        offsets[row + x] = e;
        e += counts[row + x];
    }
    if (gl_LocalInvocationIndex == 0u) rowSums[gl_WorkGroupID.x] = total.x;
}
