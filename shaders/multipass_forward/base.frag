#version 460
#extension GL_GOOGLE_include_directive : require
// Base pass: the light-independent part (ambient + emissive) plus the directional lights,
// which touch every pixel and so gain nothing from a pass of their own. Opaque and masked
// surfaces write it (depth EQUAL, no blending); blended surfaces composite it over what is
// behind them (alpha blending), which is the "first pass" of their multipass sum.
#include "include/shared.h"
#include "multipass_forward/multipass_shared.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"
#include "include/scene_inputs.glsl"

layout(constant_id = TP_MP_SPEC_DIRECTIONAL_COUNT) const uint kDirCount = 0u;
layout(constant_id = TP_MP_SPEC_DIRECTIONAL_FIRST + 0) const uint kDir0 = 0u;
layout(constant_id = TP_MP_SPEC_DIRECTIONAL_FIRST + 1) const uint kDir1 = 0u;
layout(constant_id = TP_MP_SPEC_DIRECTIONAL_FIRST + 2) const uint kDir2 = 0u;
layout(constant_id = TP_MP_SPEC_DIRECTIONAL_FIRST + 3) const uint kDir3 = 0u;

layout(location = 0) out vec4 outColor;

void main() {
    MaterialSample ms = evalFragmentMaterial();
    vec3 sum = ambientAndEmissive(ms);
    // Unrolled by the compiler: the count and the indices are constants.
    uint dirs[TP_MP_MAX_BASE_DIRECTIONAL] = uint[](kDir0, kDir1, kDir2, kDir3);
    for (uint i = 0u; i < kDirCount; ++i)
        sum += evalLight(lights[dirs[i]], ms.surface, kHasSpot);
    outColor = vec4(sum, kAlphaMode == TP_ALPHA_BLEND ? ms.alpha : 1.0);
}
