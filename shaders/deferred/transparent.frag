#version 460
#extension GL_GOOGLE_include_directive : require
// The hybrid forward pass: blended materials cannot live in a G-buffer (one surface per
// sample), so they are drawn after the lighting, back to front, alpha-blended into hdr,
// each fragment lit by its tile's transparent light list (culled by the tiled lighting
// pass against [near plane, farthest opaque depth]).
#include "include/shared.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"

layout(constant_id = TP_DEF_SPEC_TILE_SIZE) const uint kTileSize = 16u;
layout(constant_id = TP_DEF_SPEC_LIST_STRIDE) const uint kListStride = 1u;

layout(std430, set = TP_SET_PASS, binding = TP_DEF_FWD_BINDING_LISTS) readonly buffer TransparentLists {
    uint tLists[];
};

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inTangent;
layout(location = 4) in vec4 inColor;
layout(location = 0) out vec4 outColor;

void main() {
    MaterialGpu m = materials[draw.materialIndex];
    MaterialSample ms = evalMaterial(m, inPosition, inNormal, inUv, inTangent, inColor,
                                     gl_FrontFacing);
    uvec2 tile = uvec2(gl_FragCoord.xy) / kTileSize;
    uint tilesX = (frame.viewport.x + kTileSize - 1u) / kTileSize;
    uint base = (tile.y * tilesX + tile.x) * kListStride;
    uint count = min(tLists[base], kListStride - 1u); // explicit count: bounded loop
    vec3 sum = ambientAndEmissive(ms);
    for (uint i = 0u; i < count; ++i)
        sum += evalLight(lights[tLists[base + 1u + i]], ms.surface, kHasSpot);
    outColor = vec4(sum, ms.alpha);
}
