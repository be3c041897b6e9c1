#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
// Blended depth bounds (core/passes/blended_bounds.h): drawn with the blended draws'
// vertex shader in its position-only variant (scene.vert: TP_VERT_POSITION_ONLY, the same
// gl_Position and position) and the blended shading pass's rasterization state, depth test
// GREATER against the opaque depth, no depth write and no colour, so it runs for exactly the
// fragments the blended pass shades (light_assign.glsl: LaBlendedBounds says why). Each
// records its view distance into its tile's [min, max] (light_assign.h: TP_LA_BLEND_*).
//   TP_INPUTS_AT_PIXEL: the once-per-pixel variant (scene_inputs.glsl), as the shading's.
//   TP_LA_BLEND_FULL_INTERFACE: with scene.vert's every input (tests compare the two).
// A CPU device records one atomic pair per fragment; a GPU one pair per tile a subgroup meets
// (kBySubgroup, passes/blended_bounds.glsl), helpers left out: a helper invocation (a lane run
// for derivatives only) would feed its extrapolated distance into a reduction, and an elected
// lane may be a helper whose atomics are dropped (seen on an NVIDIA H100: a subgroup's
// fragments lost). So the bounds are exactly those of the shaded fragments, the same on every
// run, either way. (On lavapipe a correct reduction was slower than the atomics, and a plain
// load to skip atomics that cannot change the bound was too: docs/clustered.md; on the H200 the
// reduction took the visibility buffer's lists' pass from 0.145 to 0.119 ms: docs/visbuffer.md.)
#include "include/shared.h"
#include "include/scene_bindings.glsl"
#ifdef TP_LA_BLEND_FULL_INTERFACE
#include "include/material.glsl" // scene.vert's whole interface (tests only)
#else
#define TP_INPUTS_POSITION_ONLY 1 // position and the interpolated 1 only
#endif
#include "include/scene_inputs.glsl"
#include "include/light_assign.glsl"

// Early tests: the fragment shader has side effects, and only fragments in front of the
// opaque depth may record (as only those are shaded).
layout(early_fragment_tests) in;
#include "passes/blended_bounds.glsl"

void main() { recordBlendedBound(); }
