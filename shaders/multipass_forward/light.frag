#version 460
#extension GL_GOOGLE_include_directive : require
// One light's contribution, added into the accumulation target. Opaque and masked surfaces:
// blend ONE + ONE, alpha kept. Blended surfaces return (alpha * light, alpha) and blend
// "under" (colour: DST_ALPHA, ONE; alpha: ZERO, ONE_MINUS_SRC_ALPHA) with their triangles
// in reverse order: the target's alpha carries the transmittance of the nearer layers of
// the same draw, so after all passes a blended draw holds exactly what shading all lights
// at once and blending once gives (blended_pass.cpp, docs/multipass_forward.md).
#include "include/shared.h"
#include "multipass_forward/multipass_shared.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"
#include "include/scene_inputs.glsl"

layout(location = 0) out vec4 outColor;

void main() {
    MaterialSample ms = evalFragmentMaterial();
    vec3 c = evalLight(lights[draw.TP_MP_LIGHT_INDEX], ms.surface, kHasSpot);
    if (kAlphaMode == TP_ALPHA_BLEND)
        outColor = vec4(c * ms.alpha, ms.alpha);
    else
        outColor = vec4(c, 0.0); // the blend state keeps the destination's alpha
}
