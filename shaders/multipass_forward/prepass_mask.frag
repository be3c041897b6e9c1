#version 460
#extension GL_GOOGLE_include_directive : require
// Depth prepass of alpha-masked materials: the same alpha as every other pass (evalMaterial),
// so the EQUAL-tested passes after it see exactly the coverage the reference sees.
#include "include/shared.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"
#include "multipass_forward/inputs.glsl"

void main() {
    MaterialSample ms = evalFragmentMaterial();
    if (ms.alpha < materials[draw.materialIndex].alphaCutoff) discard;
}
