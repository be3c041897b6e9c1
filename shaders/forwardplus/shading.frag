#version 460
#extension GL_GOOGLE_include_directive : require
// Forward+ shading. Opaque and masked draws run with depth test EQUAL against the prepass
// and no discard (early depth rejection stays on: only the visible surface is shaded);
// blended draws run afterwards, back to front, with depth test GREATER and the tile's
// transparent list. Every loop is bounded by an explicit count (never a sentinel): the
// directional lights first, then the tile's list in light-index order.
#include "include/shared.h"
#include "forwardplus/forwardplus_shared.h"
#include "include/scene_bindings.glsl"
// One pipeline per material's texture indices (core/passes/material_pipelines.h).
#define TP_MATERIAL_SPEC_TEXTURES 1
#include "include/material.glsl"

// The materials again, as a uniform buffer, where they fit (include/materials_ubo.h: a CPU
// device and at most TP_MATERIALS_UBO_CAPACITY materials): the draw's material through it.
#define TP_MATERIALS_UBO_BINDING TP_FP_BINDING_MATERIALS_UBO
#define TP_MATERIALS_UBO_SPEC TP_FP_SPEC_MATERIALS_UBO
#include "include/materials_ubo.glsl"
#include "include/scene_inputs.glsl"
#include "include/light_assign.glsl"
#include "include/light_list_walk.glsl"
#include "include/shadow_light.glsl"

layout(constant_id = TP_SPEC_TILE_SIZE) const uint kTileSize = 16u;
layout(constant_id = TP_FP_SPEC_TWO_LISTS) const bool kTwoLists = false;
layout(constant_id = TP_FP_SPEC_LAYOUT) const uint kLayout = TP_FP_LAYOUT_COMPACT;
layout(constant_id = TP_FP_SPEC_NO_LIGHTS) const bool kNoLights = false;
// fp_params' directionalCount and tile grid (the same values, fixed for a plan), read per
// fragment: as constants they cost no storage-buffer load (forward_shading.cpp).
layout(constant_id = TP_FP_SPEC_DIRECTIONAL) const uint kDirectionalCount = 0u;
layout(constant_id = TP_FP_SPEC_TILES_X) const uint kTilesX = 1u;
layout(constant_id = TP_FP_SPEC_TILES_Y) const uint kTilesY = 1u;

layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_TILES) readonly buffer TileBlock {
    FpTileLists tiles[];
};
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_INDICES) readonly buffer IndexBlock {
    uint indices[];
};
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_PARAMS) readonly buffer ParamBlock {
    FpParams params;
    uint data[];
};
// The lights again, as a uniform buffer, where they fit (include/lights_ubo.h: a CPU device and
// at most TP_LIGHTS_UBO_CAPACITY lights): the directional lights first, then light k at slot
// k + directionalCount (forward_shading.cpp).
#define TP_LIGHTS_UBO_BINDING TP_FP_BINDING_LIGHTS_UBO
#define TP_LIGHTS_UBO_SPEC TP_FP_SPEC_LIGHTS_UBO
#include "include/lights_ubo.glsl"

// The scene's light `index`.
LightGpu fpLight(uint index, uint directionalCount) {
    if (kLightsUbo) return uboLight(index + directionalCount);
    return lights[index];
}

#ifdef TP_FP_LIGHT_LOOP_SUBGROUP
// --light-loop subgroup: a variant of its own, since a module that declares these
// capabilities cannot be used on a device without them (core/lightassign/knobs.h).
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#endif

#ifdef TP_FP_CLUSTERED
layout(constant_id = TP_FP_SPEC_SLICES) const uint kSlices = 16u;
layout(constant_id = TP_FP_SPEC_BLENDED_SPAN) const bool kBlendedSpan = false;
layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_CLUSTER_MASKS) readonly buffer MaskBlock {
    uint masks[];
};

// Clustered: the lights of the tile list whose bit is set in this fragment's slice, one
// 32-light word at a time: (list length / 32) words plus the cluster's lights, in list
// (ascending) order. The slice comes from the shading point's own view distance, for
// opaque and blended surfaces alike.
vec3 clusterLights(uint tileIndex, SurfaceSample surface, uint directionalCount) {
    FpTileLists t = tiles[tileIndex];
    float dist = -(frame.view * vec4(surface.position, 1.0)).z;
    LaSlicing slicing = laSlicing(t.frontNear, t.sliceNear, t.sliceScale, kSlices, laFrontSlices(kSlices, kBlendedSpan));
    uint slice = laSliceOf(dist, slicing);
    uint maskBase = data[params.lists.w + tileIndex];
    uint stride = (data[params.lists.w + tileIndex + 1u] - maskBase) / kSlices;
    uint words = (t.list[0].count + 31u) / 32u;
    uint row = maskBase + slice * stride;
    vec3 sum = vec3(0.0);
#ifdef TP_FP_LIGHT_LOOP_SUBGROUP
    // Every active lane shades the same tile (one list; the lanes' slices may differ): walk
    // the OR of the lanes' words together, so the list and light loads are the same address
    // in every lane (uniform: one load instead of one per lane on lavapipe; no divergent
    // walks on a GPU), and each lane adds a light only where its own bit is set. Each lane
    // adds its own lights in ascending order, as the lane loop does: the same sums, bit for
    // bit. The broadcasts only tell the compiler what the vote proved (equal in every lane).
    if (subgroupAllEqual(tileIndex)) {
        uint sharedWords = subgroupBroadcastFirst(words);
        uint sharedStart = subgroupBroadcastFirst(t.list[0].start);
        for (uint w = 0u; w < sharedWords; ++w) {
            uint own = masks[row + w];
            uint bits = subgroupOr(own);
            TP_FOR_EACH_BIT(bits, lsb,
                LightGpu light = fpLight(indices[sharedStart + w * 32u + uint(lsb)], directionalCount);
                if ((own & (1u << uint(lsb))) != 0u) sum += evalLightShadowed(light, surface);)
        }
        return sum;
    }
#endif
    for (uint w = 0u; w < words; ++w) {
        uint bits = masks[row + w];
        TP_FOR_EACH_BIT(bits, lsb,
            sum += evalLightShadowed(fpLight(indices[t.list[0].start + w * 32u + uint(lsb)], directionalCount), surface);)
    }
    return sum;
}
#endif

layout(location = 0) out vec4 outColor;

// Largest finite half: when the hdr target is RGBA16F (--hdr fp16, and auto), larger values
// saturate instead of becoming +Inf; an RGBA32F target (--hdr fp32) takes the fp32 sum as it is.
layout(constant_id = TP_FP_SPEC_HDR16) const bool kHdr16 = true;
const float kHalfMax = 65504.0;
vec3 storable(vec3 c) { return kHdr16 ? min(c, vec3(kHalfMax)) : c; }

void main() {
    MaterialSample ms = evalFragmentMaterial();

    vec3 sum = ambientAndEmissive(ms);
    // No light in the plan: nothing to add (lavapipe would still run the loop's body once with
    // every lane masked off, and load the tile's list: ~40 % of the 0-light pass, measured).
    if (kNoLights) {
        outColor = vec4(storable(sum), kAlphaMode == TP_ALPHA_BLEND ? ms.alpha : 1.0);
        return;
    }
    uint directionalCount = kDirectionalCount;
    uint tileIndex = laTileIndex(uvec2(gl_FragCoord.xy), kTileSize, uvec2(kTilesX, kTilesY));
#ifdef TP_FP_CLUSTERED
    for (uint i = 0u; i < directionalCount; ++i)
        sum += evalLightShadowed(kLightsUbo ? uboLight(i) : fpLight(data[i], 0u), ms.surface);
    sum += clusterLights(tileIndex, ms.surface, directionalCount);
    outColor = vec4(storable(sum), kAlphaMode == TP_ALPHA_BLEND ? ms.alpha : 1.0);
    return;
#endif
    uint list = (kTwoLists && kAlphaMode == TP_ALPHA_BLEND) ? 1u : 0u;
    uint count = tiles[tileIndex].list[list].count;
    uint start = tiles[tileIndex].list[list].start;
    // One loop over the directional lights, then the tile's list, in that order (the same
    // sums as two loops). lavapipe runs every loop body at least once, with every lane masked
    // off if need be, and a loop that tests at the top one time more than its longest lane:
    // one loop instead of two saves a whole light evaluation per fragment at every light
    // count, and testing at the bottom another where there are lights (docs/forwardplus.md).
    uint total = directionalCount + count;
    uint node = start;
    uint i = 0u;
    if (total > 0u) do {
        uint lightIndex;
        if (kLightsUbo && kLayout != TP_FP_LAYOUT_LINKED) {
            // The i-th directional light is the uniform copy's light i: one index load per
            // light, not two (lavapipe runs both sides of the branch, a masked load included).
            uint listed = 0u;
            if (i >= directionalCount) listed = indices[start + (i - directionalCount)];
            lightIndex = i < directionalCount ? i : directionalCount + listed;
        } else {
            if (i < directionalCount) {
                lightIndex = data[i];
            } else if (kLayout == TP_FP_LAYOUT_LINKED) {
                lightIndex = indices[2u * node];
                node = indices[2u * node + 1u];
            } else {
                lightIndex = indices[start + (i - directionalCount)];
            }
            if (kLightsUbo) lightIndex += directionalCount;
        }
        LightGpu light;
        if (kLightsUbo) light = uboLight(lightIndex);
        else light = lights[lightIndex];
        sum += evalLightShadowed(light, ms.surface);
        ++i;
    } while (i < total);
    outColor = vec4(storable(sum), kAlphaMode == TP_ALPHA_BLEND ? ms.alpha : 1.0);
}
