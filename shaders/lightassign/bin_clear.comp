#version 460
#extension GL_GOOGLE_include_directive : require
// light_binning, step 1: every tile's count (the difference array) to 0.
#include "lightassign/bin_common.glsl"

layout(local_size_x = 64) in;

void main() {
    const uint t = binFlatIndex();
    if (t >= bin.grid.z) return;
    counts[t] = 0u;
}
