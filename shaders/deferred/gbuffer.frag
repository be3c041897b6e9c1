#version 460
#extension GL_GOOGLE_include_directive : require
// G-buffer pass: the material at this fragment, stored in the layout the renderer planned.
// TP_INPUTS_AT_PIXEL (--msaa-shading pixel, the default): evaluated once per pixel at its
// centre and written to every covered sample, which is what makes samples of one surface
// compare equal in the edge test. Without it every sample is evaluated at its own location
// (--msaa-shading sample; scene_inputs.glsl). TP_EMISSIVE: the scene emits, so target 3
// exists (left out otherwise). TP_SAMPLE_COVERAGE (with TP_INPUTS_AT_PIXEL; the masked draws
// under MSAA): the alpha test runs at each sample's own location and writes the coverage, so
// a masked surface covers the samples the other pipelines' per-sample masked prepass and the
// centre reference cover; the material stored is still the centre's.
#include "include/shared.h"
#include "deferred/deferred_shared.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"
// The draw's material from the uniform-buffer copy on a CPU device (include/materials_ubo.h).
#define TP_MATERIALS_UBO_BINDING TP_DEF_BINDING_MATERIALS_UBO
#define TP_MATERIALS_UBO_SPEC TP_DEF_SPEC_MATERIALS_UBO
#include "include/materials_ubo.glsl"
#include "include/scene_inputs.glsl"
#include "include/gbuffer_encoding.h"

layout(constant_id = TP_DEF_SPEC_WIDE) const bool kWide = false;
#ifdef TP_SAMPLE_COVERAGE
layout(constant_id = TP_SPEC_SAMPLES) const int kSamples = 1;
#endif

layout(location = 0) out vec4 outBase;       // rgb base colour (sRGB target in compact), a occlusion
layout(location = 1) out vec4 outNormal;     // compact: octahedral rg; wide: xyz
layout(location = 2) out vec4 outRoughMetal; // r roughness, g metallic
#ifdef TP_EMISSIVE
layout(location = 3) out vec4 outEmissive;   // rgb emissive radiance
#endif

void main() {
    MaterialGpu m = materials[draw.materialIndex];
    MaterialSample ms = evalFragmentMaterial();
#ifdef TP_SAMPLE_COVERAGE
    // Sample s's alpha as sample s's own invocation of the centre reference computes it
    // (evalSampleMaterial there): the same reads, so the same samples pass. A loop to a
    // specialization constant with no exit: uniform control flow for the texture's derivatives.
    int passing = 0;
    for (int s = 0; s < kSamples; ++s)
        if (!(evalMaterialAtSample(s).alpha < m.alphaCutoff)) passing |= 1 << s;
    const int covered = gl_SampleMaskIn[0] & passing;
    if (kAlphaMode == TP_ALPHA_MASK && covered == 0) discard;
    gl_SampleMask[0] = kAlphaMode == TP_ALPHA_MASK ? covered : gl_SampleMaskIn[0];
#else
    if (kAlphaMode == TP_ALPHA_MASK && ms.alpha < m.alphaCutoff) discard;
#endif
    outBase = vec4(ms.surface.baseColor, ms.occlusion);
    vec3 n = ms.surface.normal;
    outNormal = kWide ? vec4(n, 0.0) : vec4(octEncode(n), 0.0, 0.0);
    outRoughMetal = vec4(ms.surface.roughness, ms.surface.metallic, 0.0, 0.0);
#ifdef TP_EMISSIVE
    outEmissive = vec4(ms.emissive, 0.0);
#endif
}
