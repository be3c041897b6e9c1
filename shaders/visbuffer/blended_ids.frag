#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require // the bounds (passes/blended_bounds.glsl)
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
// The blended fragment lists (--vis-blended compute): every blended draw, back to front as the
// reference draws them, depth-tested against the visibility depth (GREATER, no write, early
// tests, as the hybrid forward pass and the blended bounds are), once per pixel and primitive.
// Each fragment appends its id (vis_shared.h: the blended draws' rows follow the opaque and
// masked ones) and its coverage mask to its pixel's list; nothing is shaded here. The resolve
// (vis_blend.glsl) sorts a list by id, which is the reference's blending order: draws in
// submission order, primitives in gl_PrimitiveID order within a draw.
// Coverage is the rasterizer's before the depth test (without post-depth coverage the
// SampleMask input does not say which samples passed): under MSAA the resolve tests each
// covered sample against that sample's opaque depth itself. At 1x the early test decides.
// A full pool drops the fragment and counts it (TP_VIS_BLEND_DROPPED): never silent.
// TP_VIS_BLEND_BOUNDS: each fragment also records the blended depth bounds
// (core/passes/blended_bounds.h): the same draws, vertex shader, depth test and fragments as
// that pass's own draw, which is then not made (docs/visbuffer.md, "The blended bounds in the
// blended lists' pass"). With TP_INPUTS_AT_PIXEL under MSAA, as that pass's pixel variant.
#include "include/shared.h"
#include "visbuffer/vis_shared.h"
#include "include/scene_bindings.glsl"
#ifdef TP_VIS_BLEND_BOUNDS
#define TP_INPUTS_POSITION_ONLY 1
#include "include/scene_inputs.glsl"
#include "include/light_assign.glsl"
#include "passes/blended_bounds.glsl"
#endif

layout(early_fragment_tests) in;
layout(constant_id = TP_VIS_SPEC_TRIANGLE_BITS) const uint kTriangleBits = 20u;
layout(constant_id = TP_SPEC_SAMPLES) const uint kSamples = 1u;

layout(std430, set = TP_SET_PASS, binding = TP_VIS_BINDING_BLEND_HEADS) buffer BlendHeads {
    uint heads[];
};
layout(std430, set = TP_SET_PASS, binding = TP_VIS_BINDING_BLEND_NODES) buffer BlendNodes {
    uvec2 nodes[];
};
layout(std430, set = TP_SET_PASS, binding = TP_VIS_BINDING_BLEND_COUNTERS) buffer BlendCounters {
    uint counters[TP_VIS_BLEND_COUNTER_WORDS];
};

void main() {
#ifdef TP_VIS_BLEND_BOUNDS
    recordBlendedBound(); // before a full pool's early return: every shaded fragment counts
#endif
    const uint id = ((draw.pad0 + 1u) << kTriangleBits) | uint(gl_PrimitiveID);
    const uint coverage = uint(gl_SampleMaskIn[0]) & ((1u << kSamples) - 1u);
    const uint node = atomicAdd(counters[TP_VIS_BLEND_APPENDED], 1u);
    if (node >= counters[TP_VIS_BLEND_CAPACITY]) {
        atomicAdd(counters[TP_VIS_BLEND_DROPPED], 1u);
        return;
    }
    const uint pixel = uint(gl_FragCoord.y) * frame.viewport.x + uint(gl_FragCoord.x);
    nodes[node].x = id | (coverage << TP_VIS_BLEND_COVERAGE_SHIFT);
    nodes[node].y = atomicExchange(heads[pixel], node + 1u);
}
