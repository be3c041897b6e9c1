#version 460
#extension GL_GOOGLE_include_directive : require
// light_binning, step 4: then down each column (an invocation per column): counts[t] is now
// how many rectangles cover tile t (the compact layout's bound).
#include "lightassign/bin_common.glsl"

layout(local_size_x = 64) in;

void main() {
    const uint x = gl_GlobalInvocationID.x;
    const uint W = bin.grid.x;
    if (x >= W) return;
    uint sum = 0u;
    for (uint y = 0u; y < bin.grid.y; ++y) {
        sum += counts[y * W + x];
        counts[y * W + x] = sum;
    }
}
