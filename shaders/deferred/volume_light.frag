#version 460
#extension GL_GOOGLE_include_directive : require
// One light's contribution over its volume's back faces, added (blend ONE + ONE) to hdr.
// Depth test LESS_OR_EQUAL in reverse-Z: a back-face fragment survives where the scene
// surface is at or in front of the volume's far side, which every surface inside the
// volume is, whether the camera is outside or inside the volume (inside, the back faces
// are all that is in front of the camera). Surfaces in front of the volume also pass and
// are rejected here by the range test before the G-buffer is read.
// Under MSAA (TP_MSAA) the depth attachment is the 1x `volume_depth` from the base pass
// (the nearest sample, or 1 on edge pixels: always passes) and edge pixels are shaded per
// sample in this invocation, the rest once at the centre with the mean depth: exactly what
// the tiled pass does, through the same code (gbuffer_read.glsl).
// TP_HDR_MSAA (a blended scene under MSAA): the target is the per-sample hdr_msaa and every
// sample the back faces cover runs its own invocation: an edge pixel's sample is lit at its
// own position, any other sample with the pixel's centre value, as the tiled pass writes
// them. No depth test: a non-edge sample takes the centre's light, but on a grazing plane its
// own surface point can lie metres behind the centre's, behind the back face, so a per-sample
// test would drop it (measured: 19 % of a pixel's value lost on the courtyard floor); the
// volume's one-pixel growth keeps every sample of a lit centre inside the silhouette, and
// the range test below rejects surfaces in front of or behind the volume.
#include "include/shared.h"
#include "deferred/deferred_shared.h"
#include "include/scene_bindings.glsl"
#include "deferred/gbuffer_read.glsl"
#include "include/shadow_light.glsl"

layout(early_fragment_tests) in;
#ifdef TP_MSAA
layout(set = TP_SET_PASS, binding = TP_DEF_BINDING_EDGE_MASK) uniform sampler2D gEdge;
#endif
layout(location = 0) flat in uint inLight;
layout(location = 0) out vec4 outColor;

// evalLight(light, readSurface(...)) with its range test moved ahead of the G-buffer reads
// (the same expression, so the same outcome). The shadowed twin (TP_SHADOW_MAPS, the pass
// volume_shadowed_lights) multiplies by the light's own map, the one ShadowMaps::recordLight
// rendered right before this draw (TP_SPEC_SHADOW_LOCAL: its faces' `local` rects).
vec3 lightSample(LightGpu light, ivec2 p, uint s, vec2 offset, float depth) {
    vec3 position = reconstructPosition(p, offset, depth);
    if (light.type != TP_LIGHT_DIRECTIONAL && length(light.position - position) >= light.range)
        return vec3(0.0);
    return evalLightShadowed(light, readSurface(p, s, position));
}

#ifdef TP_MSAA
// Sample s at its own position, or (one surface) the pixel at its centre with the mean depth.
vec3 lightAtSample(LightGpu light, ivec2 p, uint s) {
    float d = fetchDepth(p, s);
    return d > 0.0 ? lightSample(light, p, s, sampleOffset(s), d) : vec3(0.0);
}

vec3 lightAtCentre(LightGpu light, ivec2 p) {
    float d = meanDepth(p);
    return d > 0.0 ? lightSample(light, p, 0u, vec2(0.5), d) : vec3(0.0);
}
#endif

void main() {
    LightGpu light = lights[inLight];
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 c = vec3(0.0);
#if defined(TP_HDR_MSAA)
    uint s = uint(gl_SampleID);
    c = texelFetch(gEdge, p, 0).r > 0.5 ? lightAtSample(light, p, s) : lightAtCentre(light, p);
#elif defined(TP_MSAA)
    if (texelFetch(gEdge, p, 0).r > 0.5) {
        for (uint s = 0u; s < kSamples; ++s) c += lightAtSample(light, p, s);
        c /= float(kSamples);
    } else {
        c = lightAtCentre(light, p);
    }
#else
    float d = fetchDepth(p, 0u);
    if (d > 0.0) c = lightSample(light, p, 0u, vec2(0.5), d);
#endif
    if (c == vec3(0.0)) discard; // adding zero changes nothing: skip the blend
    outColor = vec4(c, 0.0);
}
