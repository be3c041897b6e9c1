#version 460
#extension GL_GOOGLE_include_directive : require
// The hybrid forward pass: blended materials cannot live in a G-buffer (one surface per
// sample), so they are drawn after the lighting, back to front, alpha-blended into hdr,
// each fragment lit by its tile's transparent light list (culled by the tiled lighting
// pass against the tile's blended depth bounds; compact layout, include/light_assign.h).
// Clustered (kSlices > 0): only the lights of the fragment's cluster, through the slice rows
// the tiled pass wrote over the list (deferred_shared.h: defClusterRowsBase).
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

layout(constant_id = TP_DEF_SPEC_SLICES) const uint kSlices = 0u;
layout(std430, set = TP_SET_PASS, binding = TP_DEF_FWD_BINDING_MASKS) readonly buffer TransparentMasks {
    uint tMasks[];
};

layout(std430, set = TP_SET_PASS, binding = TP_DEF_FWD_BINDING_BLEND_BOUNDS) readonly buffer BlendBounds {
    uint blendBounds[]; // light_assign.h: TP_LA_BLEND_*
};

layout(location = 0) out vec4 outColor;

// The lights of the list whose bit is set in the slice of the shading point, one 32-light
// word at a time, in list order.
vec3 clusterLights(uint tile, uint tileCount, uint count, uint start, SurfaceSample surface) {
    float sliceNear = uintBitsToFloat(tMasks[2u * tile]);
    LaBlendedBounds b = laBlendedBounds(blendBounds[tile], blendBounds[tileCount + tile]);
    LaSlicing s = laSlicing(laFrontNear(b, sliceNear), sliceNear, uintBitsToFloat(tMasks[2u * tile + 1u]), kSlices,
                            laFrontSlices(kSlices, true));
    float dist = -(frame.view * vec4(surface.position, 1.0)).z;
    uint words = (count + 31u) / 32u;
    uint offset = start - tileCount * TP_LA_HEADER_WORDS;
    uint row = defClusterRowsBase(tileCount, offset, tile, kSlices) + laSliceOf(dist, s) * words;
    vec3 sum = vec3(0.0);
    for (uint w = 0u; w < words; ++w) {
        uint bits = tMasks[row + w];
        for (uint b = 0u; b < 32u && bits != 0u; ++b) {
            int lsb = findLSB(bits);
            bits &= bits - 1u;
            sum += evalLight(lights[tLists[start + w * 32u + uint(lsb)]], surface, kHasSpot);
        }
    }
    return sum;
}

void main() {
    MaterialSample ms = evalFragmentMaterial();
    uvec2 tiles = uvec2(laTileCount1D(frame.viewport.x, kTileSize), laTileCount1D(frame.viewport.y, kTileSize));
    uint tile = laTileIndex(uvec2(gl_FragCoord.xy), kTileSize, tiles);
    uint count = tLists[laHeaderWord(tile, TP_LA_COUNT)]; // explicit count: bounded loop
    uint start = tLists[laHeaderWord(tile, TP_LA_START)];
    vec3 sum = ambientAndEmissive(ms);
    if (kSlices > 0u) {
        outColor = vec4(sum + clusterLights(tile, tiles.x * tiles.y, count, start, ms.surface), ms.alpha);
        return;
    }
    for (uint i = 0u; i < count; ++i)
        sum += evalLight(lights[tLists[start + i]], ms.surface, kHasSpot);
    outColor = vec4(sum, ms.alpha);
}
