#version 460
#extension GL_GOOGLE_include_directive : require
// Deferred's tiled lighting: the pass library's tiled lighting (passes/tiled_lighting_*.glsl)
// over the G-buffer's surface reader, each pixel shaded by the library's default.
#include "passes/tiled_lighting_inputs.glsl"
#include "deferred/gbuffer_read.glsl"
#include "passes/tiled_lighting_shade.glsl"
#include "passes/tiled_lighting_pixel.glsl"
#include "passes/tiled_lighting_main.glsl"
