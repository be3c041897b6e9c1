#version 460
#extension GL_GOOGLE_include_directive : require
// light_binning, step 6: every light into the runs of the tiles its rectangle covers, rows
// [TP_BIN_FIRST, TP_BIN_END) of tiles per dispatch (lavapipe's loop limit: at most
// TP_BIN_FILL_BUDGET tiles per light and dispatch). A cursor per tile (atomic): the order
// inside a run depends on scheduling until step 7 sorts it.
#include "lightassign/bin_common.glsl"

layout(local_size_x = 64) in;

void main() {
    const uint index = binFlatIndex();
    if (index >= bin.grid.w) return;
    // Lights in descending order: a device that happens to run the workgroups in order (as
    // lavapipe nearly does) would leave the runs ascending and hide a broken sort from the tests.
    const uint k = bin.grid.w - 1u - index;
    const ivec4 rect = binRect(k); // what step 2 counted, computed again
    if (rect.x > rect.y || rect.z > rect.w) return;
    const uint W = bin.grid.x, light = locals[k], base = draw.TP_BIN_BASE;
    const uint y0 = max(uint(rect.z), draw.TP_BIN_FIRST), y1 = min(uint(rect.w) + 1u, draw.TP_BIN_END);
    for (uint y = y0; y < y1; ++y)
        for (uint x = uint(rect.x); x <= uint(rect.y); ++x) {
            const uint t = y * W + x;
            target[base + offsets[t] + atomicAdd(cursors[t], 1u)] = light;
        }
}
