#version 460
#extension GL_GOOGLE_include_directive : require
// The hybrid forward pass: blended materials cannot live in a G-buffer (one surface per
// sample), so they are drawn after the lighting, back to front, alpha-blended into hdr,
// each fragment lit by its tile's transparent light list (culled by the tiled lighting
// pass against the tile's blended depth bounds; compact layout, include/light_assign.h).
// Clustered (kSlices > 0): only the lights of the fragment's cluster, through the slice rows
// the tiled pass wrote over the list (passes/tiled_lighting.h: tlClusterRowsBase; under
// --light-cull binned the rows and the list are bitmasks over the tile's candidate run:
// tlMaskRowsBase, candidates.glsl).
// Rate: per sample (`sample` inputs, sample shading; 1x and --msaa-shading sample) or, built
// with TP_INPUTS_AT_PIXEL (--msaa-shading pixel under MSAA), once per pixel and primitive at
// the pixel centre, the value blended into every covered sample (scene_inputs.glsl).
// TP_SHADOW_MAPS (the _shadow twins, --shadows): each light's term times its visibility in the
// shadow atlas (include/shadow_light.glsl); blended surfaces receive shadows, cast none.
#include "include/shared.h"
#include "passes/tiled_lighting.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"
#include "include/scene_inputs.glsl"
#include "include/light_assign.glsl"
#include "include/light_list_walk.glsl"
#include "include/shadow_light.glsl"

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

// Binned (--light-cull binned): the lists and rows are bitmasks over the tile's candidates
// (passes/tiled_lighting.h: tlMaskRowsBase), walked in ascending candidate order.
layout(constant_id = TP_TL_SPEC_BINNED) const bool kBinned = false;
layout(std430, set = TP_SET_PASS, binding = TP_BF_BINDING_CANDIDATES) readonly buffer Candidates {
    uint cand[]; // deferred_shared.h: TP_TL_CAND_*
};
#include "passes/candidates.glsl"

layout(location = 0) out vec4 outColor;

// Light k of the tile's list: word w, bit b of its bitmask (binned: candidate 32 w + b), or
// index slot 32 w + b.
uint listLight(TlCandidates c, uint start, uint w, uint b) {
    return kBinned ? tlCandidateLight(c, w * 32u + b) : tLists[start + w * 32u + b];
}

// Words of the tile's list bitmask (binned) or of its slice rows (index lists); none for an
// empty list.
uint listWords(TlCandidates c, uint count) {
    return count == 0u ? 0u : kBinned ? (c.count + 31u) / 32u : (count + 31u) / 32u;
}

// The lights of the list whose bit is set in the slice of the shading point, one 32-light
// word at a time, in list order.
vec3 clusterLights(uint tile, uint tileCount, uint count, uint start, SurfaceSample surface) {
    float sliceNear = uintBitsToFloat(tMasks[2u * tile]);
    LaBlendedBounds b = laBlendedBounds(blendBounds[tile], blendBounds[tileCount + tile]);
    LaSlicing s = laSlicing(laFrontNear(b, sliceNear), sliceNear, uintBitsToFloat(tMasks[2u * tile + 1u]), kSlices,
                            laFrontSlices(kSlices, true));
    float dist = -(frame.view * vec4(surface.position, 1.0)).z;
    TlCandidates c = TlCandidates(0u, 0u, 0u);
    if (kBinned) c = tlCandidates(tile);
    uint words = listWords(c, count);
    uint offset = start - tileCount * TP_LA_HEADER_WORDS;
    uint base = kBinned ? tlMaskRowsBase(tileCount, offset, kSlices) : tlClusterRowsBase(tileCount, offset, tile, kSlices);
    uint row = base + laSliceOf(dist, s) * words;
    vec3 sum = vec3(0.0);
    for (uint w = 0u; w < words; ++w) {
        uint bits = tMasks[row + w];
        TP_FOR_EACH_BIT(bits, lsb, sum += evalLightShadowed(lights[listLight(c, start, w, uint(lsb))], surface);)
    }
    return sum;
}

// Binned, tiled: the list's bitmask, one 32-candidate word at a time.
vec3 maskLights(uint tile, uint count, uint start, SurfaceSample surface) {
    vec3 sum = vec3(0.0);
    if (count == 0u) return sum;
    TlCandidates c = tlCandidates(tile);
    uint words = listWords(c, count);
    for (uint w = 0u; w < words; ++w) {
        uint bits = tLists[start + w];
        TP_FOR_EACH_BIT(bits, lsb, sum += evalLightShadowed(lights[tlCandidateLight(c, w * 32u + uint(lsb))], surface);)
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
    if (kBinned) {
        outColor = vec4(sum + maskLights(tile, count, start, ms.surface), ms.alpha);
        return;
    }
    for (uint i = 0u; i < count; ++i)
        sum += evalLightShadowed(lights[tLists[start + i]], ms.surface);
    outColor = vec4(sum, ms.alpha);
}
