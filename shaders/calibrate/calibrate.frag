#version 460
#extension GL_GOOGLE_include_directive : require
// calibrate's fragment-stage ceilings (TP_CAL_KIND, calibrate_shared.h): the compute kinds'
// loops (FMA, light model, texture fetch) once per pixel of a full-screen triangle, or one
// constant colour (TP_CAL_FRAGMENT_FLAT) for the raster, ROP and triangle ceilings. A loop's
// result reaches the colour, so no compiler removes it; one colour write per pixel is
// negligible beside the loop.
#define TP_CAL_FRAGMENT
#include "calibrate/calibrate_shared.h"
#include "calibrate/calibrate_fma.glsl"
#include "calibrate/calibrate_light.glsl"
#include "calibrate/calibrate_texture.glsl"

layout(push_constant) uniform Push { CalPush cal; };
layout(location = 0) out vec4 outColor;
#if TP_CAL_KIND == TP_CAL_FRAGMENT_FLAT3
layout(location = 1) out vec4 outColor1;
layout(location = 2) out vec4 outColor2;
#endif

void main() {
#if TP_CAL_KIND == TP_CAL_FRAGMENT_FMA
    outColor = fmaChains(gl_FragCoord.x + gl_FragCoord.y, cal.iterations) * 1.0e-30;
#elif TP_CAL_KIND == TP_CAL_FRAGMENT_TEXTURE
    outColor = textureFetches(floor(gl_FragCoord.xy), cal.iterations) * 1.0e-30;
#elif TP_CAL_KIND == TP_CAL_FRAGMENT_LIGHT_POINT || TP_CAL_KIND == TP_CAL_FRAGMENT_LIGHT_SPOT
    const float seed = gl_FragCoord.x + gl_FragCoord.y * float(TP_CAL_TEXTURE_SIZE);
    outColor = vec4(lightEvaluations(seed, cal.iterations, TP_CAL_KIND == TP_CAL_FRAGMENT_LIGHT_SPOT) * 1.0e-30, 1.0);
#elif TP_CAL_KIND == TP_CAL_FRAGMENT_FLAT3
    outColor = vec4(1.0e-3, 0.25, 0.5, 1.0);
    outColor1 = vec4(0.25, -0.5, 0.0, 0.0);
    outColor2 = vec4(0.5, 0.75, 0.0, 0.0);
#else
    outColor = vec4(1.0e-3, 0.25, 0.5, 1.0);
#endif
}
