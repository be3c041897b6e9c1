#version 460
#extension GL_GOOGLE_include_directive : require
// light_binning, step 4b (the frame, when a consumer sizes its own runs from the counts: the
// transparent lists of deferred and the visibility buffer, clustered Forward+'s slice rows):
// one workgroup lays out TP_BIN_WORDS_SCALE * ceil((TP_BIN_WORDS_ADD + counts[t]) / 32) words
// per tile (with TP_BIN_WORDS_INDICES, a word per candidate: scale * (add + counts[t])),
// row-major, the offsets clamped to the room (as bin_scan_columns.comp clamps the runs), the
// unclamped total left for GpuBinning::overflowed.
// What HybridBlended (blended_lists.cpp: transparentListNeed, masks) and Forward+
// (light_lists.cpp: layoutMasks) laid out on the CPU from a readback per view.
#include "lightassign/bin_common.glsl"
#include "lightassign/bin_scan.glsl" // local_size_x = 64

uint tileWords(uint t) {
    const uint scale = draw.TP_BIN_WORDS_SCALE & ~TP_BIN_WORDS_INDICES, n = draw.TP_BIN_WORDS_ADD + counts[t];
    return scale * ((draw.TP_BIN_WORDS_SCALE & TP_BIN_WORDS_INDICES) != 0u ? n : (n + 31u) / 32u);
}

void main() {
    const uint tiles = bin.grid.z, room = draw.TP_BIN_WORDS_ROOM;
    const uvec2 share = binScanShare(tiles);
    uint sum = 0u;
    for (uint t = share.x; t < share.y; ++t) sum += tileWords(t);
    uvec4 total;
    uint at = binScanExclusive(uvec4(sum, 0u, 0u, 0u), total).x;
    const uint first = draw.TP_BIN_WORDS_FIRST;
    for (uint t = share.x; t < share.y; ++t) {
        words[first + t] = min(at, room);
        at += tileWords(t);
    }
    if (gl_LocalInvocationIndex == 0u) {
        words[first + tiles] = min(total.x, room);
        offsets[tiles + 1u + TP_BIN_NEED_WORDS] = total.x;
    }
}
