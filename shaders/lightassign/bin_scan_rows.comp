#version 460
#extension GL_GOOGLE_include_directive : require
// light_binning, step 3: the difference array summed along each row (an invocation per row;
// sums modulo 2^32, exact once both directions are summed: every count is below 2^32).
#include "lightassign/bin_common.glsl"

layout(local_size_x = 64) in;

void main() {
    const uint y = gl_GlobalInvocationID.x;
    if (y >= bin.grid.y) return;
    const uint W = bin.grid.x;
    uint sum = 0u;
    for (uint x = 0u; x < W; ++x) {
        sum += counts[y * W + x];
        counts[y * W + x] = sum;
    }
}
