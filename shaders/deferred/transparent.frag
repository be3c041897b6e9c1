#version 460
#extension GL_GOOGLE_include_directive : require
// The hybrid forward pass: blended materials cannot live in a G-buffer (one surface per
// sample), so they are drawn after the lighting, back to front, alpha-blended into hdr,
// each fragment lit by its tile's transparent light list (culled by the tiled lighting
// pass against [near plane, farthest opaque depth]).
#include "include/shared.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"
#include "include/scene_inputs.glsl"

layout(constant_id = TP_DEF_SPEC_TILE_SIZE) const uint kTileSize = 16u;
layout(constant_id = TP_DEF_SPEC_LIST_STRIDE) const uint kListStride = 1u;

layout(std430, set = TP_SET_PASS, binding = TP_DEF_FWD_BINDING_LISTS) readonly buffer TransparentLists {
    uint tLists[];
};

layout(location = 0) out vec4 outColor;

void main() {
    MaterialSample ms = evalFragmentMaterial();
    uvec2 tile = uvec2(gl_FragCoord.xy) / kTileSize;
    uint tilesX = (frame.viewport.x + kTileSize - 1u) / kTileSize;
    uint base = (tile.y * tilesX + tile.x) * kListStride;
    uint count = min(tLists[base], kListStride - 1u); // explicit count: bounded loop
    vec3 sum = ambientAndEmissive(ms);
    for (uint i = 0u; i < count; ++i)
        sum += evalLight(lights[tLists[base + 1u + i]], ms.surface, kHasSpot);
    outColor = vec4(sum, ms.alpha);
}
