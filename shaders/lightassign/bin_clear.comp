#version 460
#extension GL_GOOGLE_include_directive : require
// light_binning, step 1: every tile's count (the difference array, the direct counts) to 0,
// and the longest run (bin_scan_columns.comp takes the maximum).
#include "lightassign/bin_common.glsl"

layout(local_size_x = 64) in;

void main() {
    const uint t = binFlatIndex();
    if (t == 0u) { // the longest run (an atomicMax) and the sort's fallbacks (atomicAdd)
        offsets[bin.grid.z + 1u + TP_BIN_NEED_RUN] = 0u;
        offsets[bin.grid.z + 1u + TP_BIN_NEED_FALLBACKS] = 0u;
    }
    if (t >= 2u * bin.grid.z) return; // the difference array and the direct counts
    counts[t] = 0u;
}
