#version 460
#extension GL_GOOGLE_include_directive : require
// The tile depth bounds pass (core/passes/tiled_lighting.h): one 8 x 8 workgroup per tile
// reduces the depth of every sample of its pixels to the tile's nearest and farthest
// geometry depth and whether it sees the sky (include/light_assign.glsl: laDepthBoundsReduce,
// the very reduction the tiled lighting made inline), and writes them for the tiled lighting
// pass, which culls against them. A pass of its own because, inline, the 4x reduction cost
// the whole lighting kernel far more than a pass that only reads depth (docs/deferred.md: on
// the H200 at 1080p 4x, 1.1 ms of deferred's 3.1; this pass takes 0.02 ms).
//   TP_MSAA: the depth is multisampled.
#include "include/shared.h"
#include "passes/tiled_lighting.h"
#include "include/scene_bindings.glsl"
#include "passes/surface_images.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = TP_SPEC_TILE_SIZE) const uint kTileSize = 16u;
layout(constant_id = TP_SPEC_SAMPLES) const uint kSamples = 1u;

layout(set = TP_SET_PASS, binding = TP_TL_BINDING_DEPTH) uniform TP_SURFACE_TEX gDepth;
layout(std430, set = TP_SET_PASS, binding = TP_TL_BINDING_TILE_DEPTH) writeonly buffer TileDepth {
    uvec4 tileDepth[]; // per tile: its record (passes/tiled_lighting.h: TP_TL_BINDING_TILE_DEPTH)
};

#define TP_LA_DEPTH_FETCH(p, s) FETCH(gDepth, p, s).r
#include "include/light_assign.glsl"

void main() {
    uvec2 tile = gl_WorkGroupID.xy;
    laDepthBoundsBegin();
    barrier();
    laDepthBoundsReduce(tile, kTileSize, frame.viewport.xy, kSamples);
    barrier();
    if (gl_LocalInvocationIndex == 0u)
        tileDepth[tile.y * gl_NumWorkGroups.x + tile.x] = laDepthBoundsWords();
}
