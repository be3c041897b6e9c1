#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// The compute rasterizer's samples into the visibility pass's targets (--vis-raster compute and
// hybrid; visbuffer/raster_merge_pass.h): per sample (gl_SampleID makes the pass run per sample
// under MSAA), the 64-bit (depth bits, ~id) the atomic max left becomes the id and the depth
// the resolve, the blended passes and the depth export read, through the depth test
// (GREATER, as the visibility pass draws): in hybrid mode the hardware's triangles, drawn
// before it (the visibility pass, vis_raster_hw), keep the samples where they are in front
// (and at equal depth).
// A sample no triangle covered (0) writes nothing.
#include "include/shared.h"
#include "visbuffer/vis_shared.h"
#include "visbuffer/vis_raster.h"
#include "include/scene_bindings.glsl"

layout(constant_id = TP_SPEC_SAMPLES) const uint kSamples = 1u;
layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_VIS_SAMPLES) readonly buffer SampleBlock {
    uint64_t visSamples[];
};
layout(location = 0) out float outId;

void main() {
    uvec2 p = uvec2(gl_FragCoord.xy);
    uint s = kSamples > 1u ? uint(gl_SampleID) : 0u;
    uint64_t v = visSamples[(p.y * frame.viewport.x + p.x) * kSamples + s];
    uint depthBits = uint(v >> 32);
    if (depthBits == 0u) discard;
    outId = float(~uint(v & 0xffffffffUL)); // exact: ids are below 2^24 (vis_shared.h)
    gl_FragDepth = uintBitsToFloat(depthBits);
}
