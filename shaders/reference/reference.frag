#version 460
#extension GL_GOOGLE_include_directive : require
// The reference: every light at every sample (per-sample shading is forced by the pipeline
// state when MSAA is on), no culling, no intermediate storage. TP_ACCUM_FP64 accumulates
// the light sum in double precision (shaderFloat64), otherwise in fp32. Every sample reads
// its inputs at its own location (supersampling: the ground truth at any MSAA level);
// TP_INPUTS_AT_CENTER (the `center` MSAA shading) reads them at the pixel centre instead,
// but alpha-tests a masked surface at the sample, as the pipelines' per-sample masked prepass
// does: coverage per sample, shading at the centre.
// TP_POSITION_FROM_DEPTH (--reference-position depth, opaque and masked draws) lights at the
// position reconstructed from the fragment's own depth instead of the interpolated one.
#ifdef TP_ACCUM_FP64
#extension GL_ARB_gpu_shader_fp64 : require
#endif
#include "include/shared.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"
#include "include/scene_inputs.glsl"
#include "include/shadow_light.glsl"

layout(location = 0) out vec4 outColor;

#ifdef TP_POSITION_FROM_DEPTH
#include "include/unproject.glsl"
// What a deferred pipeline lights this sample at: the unprojection of its location and its
// depth as the depth buffer stores it (D32: gl_FragCoord.z is that float), by the very function
// deferred calls. gl_FragCoord.xy is the sample's location under sample shading and the pixel
// centre at 1x, equal to deferred's float(p) + offset. With TP_INPUTS_AT_CENTER: the pixel
// centre at the depth there, this sample's depth moved along the primitive's screen-space
// slope (fine derivatives across the quad; depth is affine in screen space over a primitive),
// which is what deferred's mean of the samples' depths is on one surface (the standard
// patterns are centred on the pixel). Called in uniform control flow (derivatives).
vec3 positionFromDepth() {
#ifdef TP_INPUTS_AT_CENTER
    vec2 centre = floor(gl_FragCoord.xy) + 0.5;
    vec2 d = centre - gl_FragCoord.xy;
    float z = gl_FragCoord.z + dFdxFine(gl_FragCoord.z) * d.x + dFdyFine(gl_FragCoord.z) * d.y;
    return unprojectPosition(centre, z);
#else
    return unprojectPosition(gl_FragCoord.xy, gl_FragCoord.z);
#endif
}
#endif

#ifdef TP_ACCUM_FP64
#define ACCUM dvec3
#else
#define ACCUM vec3
#endif

void main() {
    MaterialGpu m = materials[draw.materialIndex];
    MaterialSample ms = evalFragmentMaterial();
#ifdef TP_POSITION_FROM_DEPTH
    // Only the position the lights see moves (light vectors, view vector); normal and material
    // stay the interpolated ones, as the G-buffer holds them.
    ms.surface.position = positionFromDepth();
    ms.surface.toViewer = directionToViewer(ms.surface.position, ms.surface.normal);
#endif
#ifdef TP_INPUTS_AT_CENTER
    // Which samples a masked surface covers is the alpha at each sample (the pipelines'
    // masked prepass), whatever the alpha at the centre the shading reads. kAlphaMode is a
    // specialization constant: the texture read stays in uniform control flow.
    if (kAlphaMode == TP_ALPHA_MASK && evalSampleMaterial().alpha < m.alphaCutoff) discard;
#else
    if (kAlphaMode == TP_ALPHA_MASK && ms.alpha < m.alphaCutoff) discard;
#endif

    ACCUM sum = ACCUM(ambientAndEmissive(ms));
    // Two lights an iteration, in order: lavapipe ends an invocation after 65,535 loop
    // iterations and silently skips the rest (docs/shading.md), and the CLI allows 65,536.
    uint count = frame.viewport.z, i = 0u;
    for (; i + 1u < count; i += 2u) {
        sum += ACCUM(evalLightShadowed(lights[i], ms.surface));
        sum += ACCUM(evalLightShadowed(lights[i + 1u], ms.surface));
    }
    if (i < count) sum += ACCUM(evalLightShadowed(lights[i], ms.surface));
    outColor = vec4(vec3(sum), kAlphaMode == TP_ALPHA_BLEND ? ms.alpha : 1.0);
}
