#version 460
#extension GL_GOOGLE_include_directive : require
// The hybrid forward pass: blended materials cannot live in a G-buffer (one surface per
// sample), so they are drawn after the lighting, back to front, alpha-blended into hdr,
// each fragment lit by its tile's transparent light list (culled by the tiled lighting
// pass against [near plane, farthest opaque depth]; compact layout, include/light_assign.h).
#include "include/shared.h"
#include "deferred/deferred_shared.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"
#include "include/scene_inputs.glsl"
#include "include/light_assign.glsl"

layout(constant_id = TP_DEF_SPEC_TILE_SIZE) const uint kTileSize = 16u;

layout(std430, set = TP_SET_PASS, binding = TP_DEF_FWD_BINDING_LISTS) readonly buffer TransparentLists {
    uint tLists[];
};

layout(location = 0) out vec4 outColor;

void main() {
    MaterialSample ms = evalFragmentMaterial();
    uvec2 tiles = uvec2(laTileCount1D(frame.viewport.x, kTileSize), laTileCount1D(frame.viewport.y, kTileSize));
    uint tile = laTileIndex(uvec2(gl_FragCoord.xy), kTileSize, tiles);
    uint count = tLists[laHeaderWord(tile, TP_LA_COUNT)]; // explicit count: bounded loop
    uint start = tLists[laHeaderWord(tile, TP_LA_START)];
    vec3 sum = ambientAndEmissive(ms);
    for (uint i = 0u; i < count; ++i)
        sum += evalLight(lights[tLists[start + i]], ms.surface, kHasSpot);
    outColor = vec4(sum, ms.alpha);
}
