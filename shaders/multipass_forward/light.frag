#version 460
#extension GL_GOOGLE_include_directive : require
// One light's contribution, added into the accumulation target (blend ONE, ONE). Blended
// surfaces scale it by their coverage here (the same as blend factors SRC_ALPHA, ONE), so
// that after all passes a single blended layer holds (1 - a) * behind + a * (sum of all
// lights), as if it had been shaded once and blended once.
#include "include/shared.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"
#include "include/scene_inputs.glsl"

layout(location = 0) out vec4 outColor;

void main() {
    MaterialSample ms = evalFragmentMaterial();
    vec3 c = evalLight(lights[draw.TP_MP_LIGHT_INDEX], ms.surface, kHasSpot);
    if (kAlphaMode == TP_ALPHA_BLEND) c *= ms.alpha;
    outColor = vec4(c, 0.0); // alpha: the blend state keeps the destination's
}
