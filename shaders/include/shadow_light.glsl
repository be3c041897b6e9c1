// One light's radiance with its shadow, for every shading loop (the pipelines and the
// reference): evalLight() times the light's visibility where the light is shadowed
// (LightGpu.shadow != 0) and reaches the surface at all. Which visibility is compiled in:
//   TP_SHADOW_MAPS  the shadow maps (include/shadow_sample.glsl: PCF in the atlas or in one
//                   light's map), as every pipeline renders them
//   TP_SHADOW_RAYS  a shadow ray against the scene's triangles (include/shadow_rays.glsl: the
//                   reference's exact visibility)
//   neither         no shadows: evalLight() itself, the code of a run without --shadows
// Include after scene_bindings.glsl and light_model.h.
#ifndef TP_SHADOW_LIGHT_GLSL
#define TP_SHADOW_LIGHT_GLSL
#if defined(TP_SHADOW_MAPS)
#include "include/shadow_sample.glsl"
#define TP_SHADOW_VISIBILITY(light, s) shadowMapVisibility(light, s.position, s.normal)
#elif defined(TP_SHADOW_RAYS)
#include "include/shadow_rays.glsl"
#define TP_SHADOW_VISIBILITY(light, s) shadowRayVisibility(light, s.position, s.normal)
#endif

vec3 evalLightShadowed(LightGpu light, SurfaceSample s) {
    vec3 c = evalLight(light, s, kHasSpot);
#ifdef TP_SHADOW_VISIBILITY
    // Only where the light arrives: the visibility (texel fetches, a ray) costs nothing where
    // the range, the cone or the surface's facing already give zero.
    if (light.shadow != 0u && (c.r > 0.0 || c.g > 0.0 || c.b > 0.0))
        c *= TP_SHADOW_VISIBILITY(light, s);
#endif
    return c;
}
#endif
