#version 460
#extension GL_GOOGLE_include_directive : require
// --blended-lights one-pass: a blended surface shaded with ambient + emissive + every light
// in one invocation and alpha-blended once, the way forward engines light transparent
// objects (one pass, all their lights, no per-light passes) and the way the reference does.
// No light list: every light of the scene is evaluated (the light model is exactly zero past
// a light's range, so the lights that do not reach add exact zeros), so the cost grows with
// the light count times the blended fragments, while the per-light passes pay draws instead.
#include "include/shared.h"
#include "multipass_forward/multipass_shared.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"
#include "include/scene_inputs.glsl"

layout(location = 0) out vec4 outColor;

void main() {
    MaterialSample ms = evalFragmentMaterial();
    vec3 sum = ambientAndEmissive(ms);
    // Two lights an iteration, as the reference: lavapipe ends an invocation after 65,535
    // loop iterations (docs/shading.md) and the CLI allows 65,536 lights.
    uint count = frame.viewport.z, i = 0u;
    for (; i + 1u < count; i += 2u) {
        sum += evalLight(lights[i], ms.surface, kHasSpot);
        sum += evalLight(lights[i + 1u], ms.surface, kHasSpot);
    }
    if (i < count) sum += evalLight(lights[i], ms.surface, kHasSpot);
    outColor = vec4(sum, ms.alpha);
}
