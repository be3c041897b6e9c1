#version 460
#extension GL_GOOGLE_include_directive : require
// Depth prepass of alpha-masked materials (Forward+, multipass forward): the same alpha as
// every other pass (evalMaterial), so the EQUAL-tested passes after it see exactly the
// coverage the reference sees. Opaque draws need no fragment stage; blended ones are not in
// a prepass.
#include "include/shared.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"
#include "include/scene_inputs.glsl"

void main() {
    MaterialSample ms = evalFragmentMaterial();
    if (ms.alpha < materials[draw.materialIndex].alphaCutoff) discard;
}
