#version 460
#extension GL_GOOGLE_include_directive : require
// The reference: every light at every sample (per-sample shading is forced by the pipeline
// state when MSAA is on), no culling, no intermediate storage. TP_ACCUM_FP64 accumulates
// the light sum in double precision (shaderFloat64), otherwise in fp32. Every sample reads
// its inputs at its own location (supersampling: the ground truth at any MSAA level);
// TP_INPUTS_AT_CENTER (the `center` MSAA shading) reads them at the pixel centre instead.
#ifdef TP_ACCUM_FP64
#extension GL_ARB_gpu_shader_fp64 : require
#endif
#include "include/shared.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"
#include "include/scene_inputs.glsl"

layout(location = 0) out vec4 outColor;

#ifdef TP_ACCUM_FP64
#define ACCUM dvec3
#else
#define ACCUM vec3
#endif

void main() {
    MaterialGpu m = materials[draw.materialIndex];
    MaterialSample ms = evalFragmentMaterial();
    if (kAlphaMode == TP_ALPHA_MASK && ms.alpha < m.alphaCutoff) discard;

    ACCUM sum = ACCUM(ambientAndEmissive(ms));
    // Two lights an iteration, in order: lavapipe ends an invocation after 65,535 loop
    // iterations and silently skips the rest (docs/shading.md), and the CLI allows 65,536.
    uint count = frame.viewport.z, i = 0u;
    for (; i + 1u < count; i += 2u) {
        sum += ACCUM(evalLight(lights[i], ms.surface, kHasSpot));
        sum += ACCUM(evalLight(lights[i + 1u], ms.surface, kHasSpot));
    }
    if (i < count) sum += ACCUM(evalLight(lights[i], ms.surface, kHasSpot));
    outColor = vec4(vec3(sum), kAlphaMode == TP_ALPHA_BLEND ? ms.alpha : 1.0);
}
