// The one light model and the one BRDF, shared by every pipeline, the reference and the
// CPU tests. glTF metallic-roughness: GGX specular (height-correlated Smith visibility,
// Schlick Fresnel) plus Lambert diffuse; KHR_lights_punctual falloff windowed so that a
// light contributes exactly zero at its range, which makes culling at that range exact.
#ifndef TP_LIGHT_MODEL_H
#define TP_LIGHT_MODEL_H
#include "include/shared.h"

#ifndef TP_GLSL
namespace tp::gpu {
#endif

#define TP_PI 3.14159265358979f

// Window (1 - (d/r)^4)^2: 1 at d = 0, exactly 0 at and beyond d = r, C1-continuous there.
TP_INLINE float rangeWindow(float dist, float range) {
    float ratio = dist / range;
    float r2 = ratio * ratio;
    float w = clamp(1.0f - r2 * r2, 0.0f, 1.0f);
    return w * w;
}

// Inverse-square falloff with the distance clamped at TP_MIN_LIGHT_DISTANCE (a light
// touching a surface stays finite) and the range window.
TP_INLINE float distanceAttenuation(float dist, float range) {
    float d = max(dist, TP_MIN_LIGHT_DISTANCE);
    return rangeWindow(dist, range) / (d * d);
}

// Smooth cone falloff (KHR_lights_punctual): 0 outside the outer cone, 1 inside the inner.
// The cosine is at most 1; rounding puts it a little above 1 at about one point in eight on
// the axis, which a zero cone (outer 0: offset = -scale = -1e4) turns into light: clamped,
// scale + offset is exactly 0 there (stress case spot-zero-cone).
TP_INLINE float spotAttenuation(vec3 toLight, vec3 spotDirection, float scale, float offset) {
    float cd = min(dot(spotDirection, -toLight), 1.0f);
    float a = clamp(cd * scale + offset, 0.0f, 1.0f);
    return a * a;
}

// What the BRDF needs of a surface point; filled from the material by the caller.
struct SurfaceSample {
    vec3 position;
    vec3 normal;    // unit, facing the viewer for double-sided surfaces
    vec3 toViewer;  // unit
    vec3 baseColor; // linear
    float metallic;
    float roughness; // perceptual; clamped to TP_MIN_ROUGHNESS in brdf()
};

// f(l, v) * cos(theta_l): the radiance leaving toward the viewer per unit irradiance.
TP_INLINE vec3 brdfCos(SurfaceSample s, vec3 l) {
    vec3 n = s.normal;
    vec3 v = s.toViewer;
    float nDotL = clamp(dot(n, l), 0.0f, 1.0f);
    if (nDotL <= 0.0f) return vec3(0.0f);
    float nDotV = max(dot(n, v), 1e-4f);
    vec3 h = normalize(l + v);
    float nDotH = clamp(dot(n, h), 0.0f, 1.0f);
    float vDotH = clamp(dot(v, h), 0.0f, 1.0f);

    float rough = max(s.roughness, TP_MIN_ROUGHNESS);
    float a = rough * rough;
    float a2 = a * a;
    float dDenom = nDotH * nDotH * (a2 - 1.0f) + 1.0f;
    float D = a2 / (TP_PI * dDenom * dDenom);
    float visV = nDotL * sqrt(nDotV * nDotV * (1.0f - a2) + a2);
    float visL = nDotV * sqrt(nDotL * nDotL * (1.0f - a2) + a2);
    float Vis = 0.5f / max(visV + visL, 1e-7f);

    vec3 f0 = mix(vec3(0.04f), s.baseColor, s.metallic);
    float fw = pow(1.0f - vDotH, 5.0f);
    vec3 F = f0 + (vec3(1.0f) - f0) * fw;
    vec3 diffuseColor = s.baseColor * (1.0f - s.metallic);
    vec3 diffuse = (vec3(1.0f) - F) * diffuseColor * (1.0f / TP_PI);
    return (diffuse + F * (D * Vis)) * nDotL;
}

// Radiance toward the viewer from one light. hasSpot = 0 compiles the spot path out
// (a specialization constant in the shaders).
TP_INLINE vec3 evalLight(LightGpu light, SurfaceSample s, bool hasSpot) {
    vec3 l;
    float atten;
    if (light.type == TP_LIGHT_DIRECTIONAL) {
        l = -light.direction;
        atten = 1.0f;
    } else {
        vec3 d = light.position - s.position;
        float dist = length(d);
        if (dist >= light.range) return vec3(0.0f);
        l = dist > 0.0f ? d / dist : s.normal;
        atten = distanceAttenuation(dist, light.range);
        if (hasSpot && light.type == TP_LIGHT_SPOT)
            atten *= spotAttenuation(l, light.direction, light.spotScale, light.spotOffset);
    }
    if (atten <= 0.0f) return vec3(0.0f);
    return brdfCos(s, l) * light.color * atten;
}

#ifndef TP_GLSL
} // namespace tp::gpu
#endif
#endif
