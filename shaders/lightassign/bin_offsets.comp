#version 460
#extension GL_GOOGLE_include_directive : require
// light_binning, step 5: offsets = the exclusive prefix sum of the counts, tiles + 1 words
// (the compact layout). One workgroup: each invocation sums a contiguous chunk, invocation 0
// scans the chunk sums, each writes its chunk's offsets. At most 2 * tiles / 256 + 256 loop
// iterations per invocation (16,384 tiles of 8 x 8 pixels at 16384 x 16384 fit lavapipe's
// limit); the frame's cost is a few thousand tiles.
#include "lightassign/bin_common.glsl"

layout(local_size_x = TP_BIN_SCAN_GROUP) in;

shared uint chunkStart[TP_BIN_SCAN_GROUP];

void main() {
    const uint tiles = bin.grid.z, lane = gl_LocalInvocationIndex;
    const uint chunk = (tiles + TP_BIN_SCAN_GROUP - 1u) / TP_BIN_SCAN_GROUP;
    const uint begin = min(lane * chunk, tiles), end = min(begin + chunk, tiles);
    uint sum = 0u;
    for (uint t = begin; t < end; ++t) sum = binSaturatingAdd(sum, counts[t]);
    chunkStart[lane] = sum;
    barrier();
    if (lane == 0u) {
        uint run = 0u;
        for (uint i = 0u; i < TP_BIN_SCAN_GROUP; ++i) {
            const uint s = chunkStart[i];
            chunkStart[i] = run;
            run = binSaturatingAdd(run, s);
        }
        offsets[tiles] = run;
    }
    barrier();
    uint run = chunkStart[lane];
    for (uint t = begin; t < end; ++t) {
        offsets[t] = run;
        run = binSaturatingAdd(run, counts[t]);
    }
}
