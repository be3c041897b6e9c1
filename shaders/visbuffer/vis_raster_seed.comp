#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// At 1x, the compute rasterizer's samples become the visibility targets' first contents
// (--vis-raster compute|hybrid; visbuffer/raster_merge_pass.h): per pixel, the 64-bit
// (depth bits, ~id) the atomic max left is written as the id, into the R32 id image, and as the
// depth, into an fp32 plane that vis_raster_seed_copy copies into the D32 depth image (a shader
// cannot store to a depth image). A pixel no triangle covered (0) gets the visibility pass's
// clear values: id 0 (no geometry), depth 0 (reverse-Z's far). The hardware's draws (hybrid)
// then depth-test against these. This replaces the full-screen merge draw after them, which
// runs on the graphics SMs (on the H200 4 of 132); at 1x the depth image can be a copy's
// destination (a multisampled one cannot: the merge stays there).
#include "include/shared.h"
#include "visbuffer/vis_shared.h"
#include "visbuffer/vis_raster.h"
#include "include/scene_bindings.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_SEED_SAMPLES) readonly buffer SampleBlock {
    uint64_t visSamples[];
};
layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_SEED) writeonly buffer SeedBlock {
    float seedDepth[];
};
layout(set = TP_SET_PASS, binding = TP_VR_BINDING_SEED_IDS, r32f) uniform writeonly image2D ids;

void main() {
    const uvec2 size = uvec2(frame.viewport.xy);
    const uvec2 p = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(p, size))) return;
    const uint i = p.y * size.x + p.x;
    const uint64_t v = visSamples[i];
    const uint depthBits = uint(v >> 32);
    // Exact: ids are below 2^24 (vis_shared.h), as the merge writes them.
    imageStore(ids, ivec2(p), vec4(depthBits == 0u ? 0.0 : float(~uint(v & 0xffffffffUL))));
    seedDepth[i] = uintBitsToFloat(depthBits);
}
