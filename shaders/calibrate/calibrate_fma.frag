#version 460
#extension GL_GOOGLE_include_directive : require
// calibrate's fragment-stage FMA ceiling: the compute kind's loop (calibrate_fma.glsl) once per
// pixel of a full-screen triangle. The colour written depends on every step, so no compiler
// removes the loop; one RGBA8 write per pixel is negligible beside it.
#include "calibrate/calibrate_shared.h"
#include "calibrate/calibrate_fma.glsl"

layout(push_constant) uniform Push { CalPush cal; };
layout(location = 0) out vec4 outColor;

void main() {
    outColor = fmaChains(gl_FragCoord.x + gl_FragCoord.y, cal.iterations) * 1.0e-30;
}
