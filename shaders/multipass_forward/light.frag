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
#include "include/shadow_light.glsl"

layout(location = 0) out vec4 outColor;

void main() {
    MaterialSample ms = evalFragmentMaterial();
    // The _shadow twin (--shadows) multiplies by the map this pass rendered for the light
    // (one light's map: TP_SPEC_SHADOW_LOCAL); the plain shader is evalLight() itself.
    vec3 c = evalLightShadowed(lights[draw.TP_MP_LIGHT_INDEX], ms.surface);
    if (kAlphaMode == TP_ALPHA_BLEND)
        outColor = vec4(c * ms.alpha, ms.alpha);
    else
        outColor = vec4(c, 0.0); // the blend state keeps the destination's alpha
}
