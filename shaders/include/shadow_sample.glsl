// Shadow-map visibility (docs/shadows.md, "The filter and the bias"): the faces and the depth
// map of set TP_SET_SHADOW, sampled with texelFetch (no sampler state: the same texels and
// weights on every device). Include through include/shadow_light.glsl (TP_SHADOW_MAPS).
//
//   face     a point light's cube face is the major axis of the light-to-surface vector
//   offset   the receiver moves along its normal by TP_SHADOW_NORMAL_OFFSET texel footprints
//            (the footprint at its distance: params.x * distance): past the depth steps of the
//            texels the kernel reads around it on a surface tilted toward the light
//   bias     and is compared TP_SHADOW_DEPTH_BIAS footprints nearer to the light
//   filter   PCF over (2 TP_SHADOW_PCF_RADIUS + 1)^2 texels around the nearest one, box weights,
//            clamped to the face (no reads across a face's or a neighbour's edge)
#ifndef TP_SHADOW_SAMPLE_GLSL
#define TP_SHADOW_SAMPLE_GLSL
#include "include/shadows.h"

layout(constant_id = TP_SPEC_SHADOW_LOCAL) const bool kShadowLocal = false;
#include "include/shadow_faces.glsl"
layout(set = TP_SET_SHADOW, binding = TP_BINDING_SHADOW_MAP) uniform sampler2D shadowMap;
layout(constant_id = TP_SPEC_SHADOW_BUFFER) const bool kShadowBuffer = false;
layout(constant_id = TP_SPEC_SHADOW_ATLAS_WIDTH) const uint kShadowAtlasWidth = 1u;
layout(std430, set = TP_SET_SHADOW, binding = TP_BINDING_SHADOW_DEPTH) readonly buffer ShadowDepth {
    uint shadowDepth[]; // kShadowBuffer: the atlas's texels, row-major
};

// The stored depth of atlas (or map) texel t.
float shadowTexel(ivec2 t) {
    if (kShadowBuffer) return uintBitsToFloat(shadowDepth[uint(t.y) * kShadowAtlasWidth + uint(t.x)]);
    return texelFetch(shadowMap, t, 0).r;
}

// The face of a light (first = LightGpu.shadow - 1) that sees light-relative position d.
uint shadowFaceIndex(uint first, vec3 d) {
    if (shadowFaces[first].params.z < 6.0) return first;
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z) return first + (d.x >= 0.0 ? 0u : 1u);
    if (a.y >= a.z) return first + (d.y >= 0.0 ? 2u : 3u);
    return first + (d.z >= 0.0 ? 4u : 5u);
}

float shadowMapVisibility(LightGpu light, vec3 position, vec3 normal) {
    const uint first = light.shadow - 1u;
    vec3 d = position - light.position;
    uint fi = shadowFaceIndex(first, d);
    float footprint = shadowFaces[fi].params.x * (shadowFaces[fi].lightProj * vec4(d, 1.0)).w;
    d += normal * (TP_SHADOW_NORMAL_OFFSET * footprint);
    fi = shadowFaceIndex(first, d);
    ShadowFace f = shadowFaces[fi];
    vec4 clip = f.lightProj * vec4(d, 1.0);
    if (clip.w <= f.params.y) return 1.0; // nearer than the near plane or behind a spot: unseen
    // Reverse-Z: stored depth = near / distance; the receiver, moved nearer by the bias.
    float receiver = f.params.y / (clip.w * (1.0 - TP_SHADOW_DEPTH_BIAS * f.params.x));
    int edge = int(f.atlas.z);
    ivec2 origin = ivec2(kShadowLocal ? f.local.xy : f.atlas.xy);
    ivec2 centre = ivec2(floor((clip.xy / clip.w * 0.5 + 0.5) * float(edge)));
    float lit = 0.0;
    for (int dy = -TP_SHADOW_PCF_RADIUS; dy <= TP_SHADOW_PCF_RADIUS; ++dy)
        for (int dx = -TP_SHADOW_PCF_RADIUS; dx <= TP_SHADOW_PCF_RADIUS; ++dx) {
            ivec2 q = clamp(centre + ivec2(dx, dy), ivec2(0), ivec2(edge - 1));
            lit += receiver >= shadowTexel(origin + q) ? 1.0 : 0.0;
        }
    const float taps = float((2 * TP_SHADOW_PCF_RADIUS + 1) * (2 * TP_SHADOW_PCF_RADIUS + 1));
    return lit / taps;
}
#endif
