#version 460
#extension GL_GOOGLE_include_directive : require
// Forward+ depth prepass, alpha-masked draws: the material's alpha decides coverage exactly
// as in every other pass (evalMaterial; everything but alpha is dead code). Opaque draws
// have no fragment shader at all; blended draws are not in the prepass.
#include "include/shared.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inTangent;
layout(location = 4) in vec4 inColor;

void main() {
    MaterialGpu m = materials[draw.materialIndex];
    MaterialSample ms = evalMaterial(m, inPosition, inNormal, inUv, inTangent, inColor, gl_FrontFacing);
    if (ms.alpha < m.alphaCutoff) discard;
}
