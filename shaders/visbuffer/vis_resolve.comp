#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility buffer's resolve: the pass library's tiled lighting
// (passes/tiled_lighting_*.glsl) over the visibility buffer's surface reader, with its own
// pixel (one shade per distinct triangle, blended fragments composited under TP_VIS_BLEND).
#include "passes/tiled_lighting_inputs.glsl"
#include "visbuffer/vis_read.glsl"
#include "passes/tiled_lighting_shade.glsl"
#include "visbuffer/vis_shade_pixel.glsl"
#include "passes/tiled_lighting_main.glsl"
