#version 460
#extension GL_GOOGLE_include_directive : require
// G-buffer pass: the material at this fragment, stored in the layout the renderer planned.
// TP_INPUTS_AT_PIXEL (--msaa-shading pixel, the default): evaluated once per pixel at its
// centre and written to every covered sample, which is what makes samples of one surface
// compare equal in the edge test. Without it every sample is evaluated at its own location
// (--msaa-shading sample; scene_inputs.glsl). TP_EMISSIVE: the scene emits, so target 3
// exists (left out otherwise).
#include "include/shared.h"
#include "deferred/deferred_shared.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"
#include "include/scene_inputs.glsl"
#include "include/gbuffer_encoding.h"

layout(constant_id = TP_DEF_SPEC_WIDE) const bool kWide = false;

layout(location = 0) out vec4 outBase;       // rgb base colour (sRGB target in compact), a occlusion
layout(location = 1) out vec4 outNormal;     // compact: octahedral rg; wide: xyz
layout(location = 2) out vec4 outRoughMetal; // r roughness, g metallic
#ifdef TP_EMISSIVE
layout(location = 3) out vec4 outEmissive;   // rgb emissive radiance
#endif

void main() {
    MaterialGpu m = materials[draw.materialIndex];
    MaterialSample ms = evalFragmentMaterial();
    if (kAlphaMode == TP_ALPHA_MASK && ms.alpha < m.alphaCutoff) discard;
    outBase = vec4(ms.surface.baseColor, ms.occlusion);
    vec3 n = ms.surface.normal;
    outNormal = kWide ? vec4(n, 0.0) : vec4(octEncode(n), 0.0, 0.0);
    outRoughMetal = vec4(ms.surface.roughness, ms.surface.metallic, 0.0, 0.0);
#ifdef TP_EMISSIVE
    outEmissive = vec4(ms.emissive, 0.0);
#endif
}
