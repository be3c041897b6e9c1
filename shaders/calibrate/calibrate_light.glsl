// The light-model loop of calibrate's light-cost ceilings, compute (TP_CAL_LIGHT_*) and fragment
// (TP_CAL_FRAGMENT_LIGHT_*): one evalLight (light_model.h, the code every pipeline and the
// reference shade with) per step. The light is made in registers from the step, not loaded:
// a pass's light loads are bytes, placed against the bandwidth ceilings. It is always in range
// and above the surface, so every evaluation runs the whole BRDF, as a lit sample does.
#ifndef TP_CALIBRATE_LIGHT_GLSL
#define TP_CALIBRATE_LIGHT_GLSL
#include "include/light_model.h"

vec3 lightEvaluations(float seed, uint steps, bool spot) {
    SurfaceSample s;
    s.position = vec3(fract(seed * 0.618034) * 2.0 - 1.0, 0.0, fract(seed * 0.414214) * 2.0 - 1.0);
    s.normal = normalize(vec3(0.05 * fract(seed * 0.3), 1.0, 0.05));
    s.toViewer = normalize(vec3(0.3, 1.0, 0.6) - s.position);
    s.baseColor = vec3(0.8, 0.6, 0.4);
    s.metallic = fract(seed * 0.1);
    s.roughness = 0.3 + 0.5 * fract(seed * 0.7);
    LightGpu light;
    light.range = 8.0;
    light.direction = vec3(0.0, -1.0, 0.0);
    light.type = spot ? TP_LIGHT_SPOT : TP_LIGHT_POINT;
    light.color = vec3(1.0);
    light.spotScale = 4.0;   // cone: outer cosine 0.5, inner 0.75
    light.spotOffset = -2.0;
    vec3 sum = vec3(0.0);
    for (uint k = 0u; k < steps; ++k) {
        const float f = float(k & 15u);
        light.position = s.position + vec3(f * 0.1 - 0.75, 1.0 + f * 0.05, 0.5 - f * 0.05);
        sum += evalLight(light, s, spot);
    }
    return sum;
}
#endif
