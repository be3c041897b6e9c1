// Reading the G-buffer back: bindings, position reconstruction, the surface one sample
// holds, its ambient + emissive term and the MSAA edge test. One copy, included by the
// tiled compute pass and by every light-volume shader, so both lighting modes shade with
// the very same code (their results differ only in the order the light sum is added).
// The includer defines TP_MSAA (per-sample G-buffer) and TP_EMISSIVE (0/1) as the variant
// needs, and TP_SURFACE_DEPTH_ONLY when it reads depth alone.
#ifndef TP_GBUFFER_READ_GLSL
#define TP_GBUFFER_READ_GLSL
#include "include/gbuffer_encoding.h"
#include "deferred/deferred_shared.h"
#include "include/light_model.h"
#include "include/tile_culling.glsl" // viewZFromDepth
#include "include/unproject.glsl"

layout(constant_id = TP_DEF_SPEC_WIDE) const bool kWide = false;
layout(constant_id = TP_SPEC_SAMPLES) const uint kSamples = 1u;
layout(constant_id = TP_TL_SPEC_EVERY_SAMPLE) const bool kEverySample = false;

#include "passes/surface_images.glsl"
#ifndef TP_SURFACE_DEPTH_ONLY
layout(set = TP_SET_PASS, binding = TP_DEF_BINDING_BASE) uniform TP_SURFACE_TEX gBase;
layout(set = TP_SET_PASS, binding = TP_DEF_BINDING_NORMAL) uniform TP_SURFACE_TEX gNormal;
layout(set = TP_SET_PASS, binding = TP_DEF_BINDING_ROUGH_METAL) uniform TP_SURFACE_TEX gRoughMetal;
#if TP_EMISSIVE
layout(set = TP_SET_PASS, binding = TP_DEF_BINDING_EMISSIVE) uniform TP_SURFACE_TEX gEmissive;
#endif
#endif
layout(set = TP_SET_PASS, binding = TP_TL_BINDING_DEPTH) uniform TP_SURFACE_TEX gDepth;

#include "include/sample_locations.glsl"

float fetchDepth(ivec2 p, uint s) { return FETCH(gDepth, p, s).r; }

// Mean of the samples' depths: a one-surface pixel is shaded once at its centre with it
// (depth is affine in screen space over a plane and the standard patterns are centred).
float meanDepth(ivec2 p) {
    float d = 0.0;
    for (uint s = 0u; s < kSamples; ++s) d += fetchDepth(p, s);
    return d / float(kSamples);
}

// Camera-relative position of sample location p + offset at a reverse-Z depth: the shared
// unprojection (include/unproject.glsl), which the reference's `--reference-position depth`
// also calls, so that the two cannot drift apart.
vec3 reconstructPosition(ivec2 p, vec2 offset, float depth) {
    return unprojectPosition(vec2(float(p.x) + offset.x, float(p.y) + offset.y), depth);
}

#ifndef TP_SURFACE_DEPTH_ONLY
vec3 fetchNormal(ivec2 p, uint s) {
    vec4 e = FETCH(gNormal, p, s);
    return kWide ? e.xyz : octDecode(e.xy);
}

vec3 fetchEmissive(ivec2 p, uint s) {
#if TP_EMISSIVE
    return FETCH(gEmissive, p, s).rgb;
#else
    return vec3(0.0);
#endif
}

// The surface sample s of pixel p holds, at `position` (reconstructed by the caller).
SurfaceSample readSurface(ivec2 p, uint s, vec3 position) {
    vec4 base = FETCH(gBase, p, s);
    vec2 rm = FETCH(gRoughMetal, p, s).rg;
    SurfaceSample ss;
    ss.position = position;
    ss.normal = fetchNormal(p, s);
    ss.toViewer = directionToViewer(ss.position, ss.normal);
    ss.baseColor = base.rgb;
    ss.roughness = rm.r;
    ss.metallic = rm.g;
    return ss;
}

// The surface sample s of pixel p holds, lit at the position reconstructed from `depth` at
// the sample location p + offset (the tiled pass's entry point to every surface reader).
SurfaceSample readSurfaceAt(ivec2 p, uint s, vec2 offset, float depth) {
    return readSurface(p, s, reconstructPosition(p, offset, depth));
}

// Roughness and metallic of sample 0 (--debug's channel image).
vec2 debugRoughMetal(ivec2 p) { return FETCH(gRoughMetal, p, 0u).rg; }

// material.glsl's ambientAndEmissive, from the stored occlusion (base.a) and emissive.
vec3 ambientEmissive(ivec2 p, uint s) {
    vec4 base = FETCH(gBase, p, s);
    float metallic = FETCH(gRoughMetal, p, s).g;
    return frame.ambient.rgb * base.rgb * (1.0 - metallic) * base.a + fetchEmissive(p, s);
}

// Whether the samples' depths lie on one plane over the pixel (reverse-Z depth is affine in
// screen space over a planar primitive). Least squares over the standard pattern, which is
// centred on the pixel (mean offset 0.5), so the fit's constant is the mean depth; then the
// largest residual against 2^-16 of the depth (256 ulps: the rasterizer's own rounding of
// the plane equation stays far below it). Two samples fit any plane: there the view depths
// must agree to 1 % instead.
bool depthsCoplanar(ivec2 p) {
    if (kSamples < 4u) {
        float z0 = viewZFromDepth(fetchDepth(p, 0u), frame.invProj);
        float z1 = viewZFromDepth(fetchDepth(p, 1u), frame.invProj);
        return abs(z1 - z0) <= 0.01 * abs(z0);
    }
    float mean = meanDepth(p), dmax = 0.0;
    vec2 gx = vec2(0.0);  // sum of u * (d - mean)
    vec3 suu = vec3(0.0); // sums of u.x^2, u.y^2, u.x * u.y
    for (uint s = 0u; s < kSamples; ++s) {
        vec2 u = sampleOffset(s) - 0.5;
        float d = fetchDepth(p, s);
        gx += u * (d - mean);
        suu += vec3(u.x * u.x, u.y * u.y, u.x * u.y);
        dmax = max(dmax, d);
    }
    vec2 grad = inverse(mat2(suu.x, suu.z, suu.z, suu.y)) * gx;
    float worst = 0.0;
    for (uint s = 0u; s < kSamples; ++s)
        worst = max(worst, abs(fetchDepth(p, s) - mean - dot(grad, sampleOffset(s) - 0.5)));
    return worst <= dmax * (1.0 / 65536.0);
}

// Lauritzen 2010: a pixel is an edge when its samples do not hold the same surface: coverage
// by geometry on some samples only, a different G-buffer value (the pixel-rate G-buffer pass
// writes one value per primitive), or depths off one plane (two surfaces of one material,
// e.g. a step). A plane seen at a grazing angle is not an edge however fast its depth
// changes across the pixel: one shading at its centre is what once-per-pixel shading means
// there (a 1 % view-depth test marked 59 % of a 320x180 courtyard's pixels as edges).
// With a sample-rate G-buffer (kEverySample) every pixel that holds geometry counts as an
// edge: each sample is lit from its own material, as the supersampled reference does.
bool isEdge(ivec2 p) {
    if (kEverySample) {
        for (uint s = 0u; s < kSamples; ++s)
            if (fetchDepth(p, s) > 0.0) return true;
        return false;
    }
    float d0 = fetchDepth(p, 0u);
    vec4 b0 = FETCH(gBase, p, 0u), n0 = FETCH(gNormal, p, 0u), r0 = FETCH(gRoughMetal, p, 0u);
    vec3 e0 = fetchEmissive(p, 0u);
    for (uint s = 1u; s < kSamples; ++s) {
        float d = fetchDepth(p, s);
        if ((d > 0.0) != (d0 > 0.0)) return true;
        if (d0 <= 0.0) continue;
        if (FETCH(gBase, p, s) != b0 || FETCH(gNormal, p, s) != n0 ||
            FETCH(gRoughMetal, p, s) != r0 || fetchEmissive(p, s) != e0)
            return true;
    }
    return d0 > 0.0 && !depthsCoplanar(p);
}
#endif
#endif
