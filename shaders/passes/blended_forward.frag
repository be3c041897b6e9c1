#version 460
#extension GL_GOOGLE_include_directive : require
// The hybrid forward pass: blended materials cannot live in a G-buffer (one surface per
// sample), so they are drawn after the lighting, back to front, alpha-blended into hdr,
// each fragment lit by its tile's transparent light list (culled by the tiled lighting
// pass against the tile's blended depth bounds; compact layout, include/light_assign.h): light
// indices, under --light-cull binned too, read as Forward+ reads its lists (a bitmask over
// the tile's candidates cost a walk of ceil(candidates / 32) words and a candidate load per
// light: 3.34 against 2.88 ms on the H200, docs/deferred.md).
// Clustered (kSlices > 0): only the lights of the fragment's cluster, through the slice rows
// the tiled pass wrote over the list (passes/tiled_lighting.h: tlClusterRowsBase).
// Rate: per sample (`sample` inputs, sample shading; 1x and --msaa-shading sample) or, built
// with TP_INPUTS_AT_PIXEL (--msaa-shading pixel under MSAA), once per pixel and primitive at
// the pixel centre, the value blended into every covered sample (scene_inputs.glsl).
// TP_SHADOW_MAPS (the _shadow twins, --shadows): each light's term times its visibility in the
// shadow atlas (include/shadow_light.glsl); blended surfaces receive shadows, cast none.
#include "include/shared.h"
#include "passes/tiled_lighting.h"
// A pipeline per material, its texture indices compiled in (core/passes/material_pipelines.h).
#define TP_MATERIAL_SPEC_TEXTURES 1
#include "include/scene_bindings.glsl"
#include "include/material.glsl"
// The draw's material from the uniform-buffer copy on a CPU device (include/materials_ubo.h).
#define TP_MATERIALS_UBO_BINDING TP_BF_BINDING_MATERIALS_UBO
#define TP_MATERIALS_UBO_SPEC TP_BF_SPEC_MATERIALS_UBO
#include "include/materials_ubo.glsl"
#include "include/scene_inputs.glsl"
#include "include/light_assign.glsl"
#include "include/light_list_walk.glsl"
#include "include/shadow_light.glsl"
// The lights' uniform-buffer copy (include/lights_ubo.h: read on a CPU device), the tiled
// lighting's own (its slot k holds light k).
#define TP_LIGHTS_UBO_BINDING TP_BF_BINDING_LIGHTS_UBO
#define TP_LIGHTS_UBO_SPEC TP_TL_SPEC_LIGHTS_UBO
#include "include/lights_ubo.glsl"

layout(constant_id = TP_SPEC_TILE_SIZE) const uint kTileSize = 16u;

layout(std430, set = TP_SET_PASS, binding = TP_BF_BINDING_LISTS) readonly buffer TransparentLists {
    uint tLists[];
};

layout(constant_id = TP_TL_SPEC_SLICES) const uint kSlices = 0u;
layout(std430, set = TP_SET_PASS, binding = TP_BF_BINDING_MASKS) readonly buffer TransparentMasks {
    uint tMasks[];
};

layout(std430, set = TP_SET_PASS, binding = TP_BF_BINDING_BLEND_BOUNDS) readonly buffer BlendBounds {
    uint blendBounds[]; // light_assign.h: TP_LA_BLEND_*
};

// Where the ambient and emissive term joins the lights' sum: after them (summed from zero)
// under --light-cull binned, as when its lists were bitmasks walked in a function of their
// own; before them (each light added to it) under --light-cull all. The same lights in the
// same order either way: only the association differs, and each keeps its image to the bit
// (one ulp on 2.3 % of courtyard-small's pixels, the blended cloth, between the two).
layout(constant_id = TP_TL_SPEC_BINNED) const bool kAmbientLast = false;

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
    uint row = tlClusterRowsBase(tileCount, start - tileCount * TP_LA_HEADER_WORDS, tile, kSlices) +
               laSliceOf(dist, s) * words;
    vec3 sum = vec3(0.0);
    for (uint w = 0u; w < words; ++w) {
        uint bits = tMasks[row + w];
        TP_FOR_EACH_BIT(bits, lsb, sum += evalLightShadowed(sceneLight(tLists[start + w * 32u + uint(lsb)]), surface);)
    }
    return sum;
}

void main() {
    MaterialSample ms = evalFragmentMaterial();
    uvec2 tiles = uvec2(laTileCount1D(frame.viewport.x, kTileSize), laTileCount1D(frame.viewport.y, kTileSize));
    uint tile = laTileIndex(uvec2(gl_FragCoord.xy), kTileSize, tiles);
    uint count = tLists[laHeaderWord(tile, TP_LA_COUNT)]; // explicit count: bounded loop
    uint start = tLists[laHeaderWord(tile, TP_LA_START)];
    vec3 ambient = ambientAndEmissive(ms);
    if (kSlices > 0u) {
        outColor = vec4(ambient + clusterLights(tile, tiles.x * tiles.y, count, start, ms.surface), ms.alpha);
        return;
    }
    vec3 sum = kAmbientLast ? vec3(0.0) : ambient;
    for (uint i = 0u; i < count; ++i)
        sum += evalLightShadowed(sceneLight(tLists[start + i]), ms.surface);
    outColor = vec4(kAmbientLast ? ambient + sum : sum, ms.alpha);
}
