// The one tonemap, used by the CPU (PNG output) and the GPU (viewer) alike:
// scene value * 2^exposureEv, then the ACES filmic curve fitted by Narkowicz (2015),
// then the sRGB transfer function. Negative or NaN inputs map to 0.
#ifndef TP_TONEMAP_H
#define TP_TONEMAP_H
#include "include/glsl_cpp.h"

#ifndef TP_GLSL
namespace tp::gpu {
#endif

TP_INLINE vec3 acesFitted(vec3 x) {
    x = max(x, vec3(0.0f));
    vec3 y = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
    return clamp(y, 0.0f, 1.0f);
}

TP_INLINE float srgbEncode(float c) {
    return c <= 0.0031308f ? 12.92f * c : 1.055f * pow(c, 1.0f / 2.4f) - 0.055f;
}

TP_INLINE float srgbDecode(float c) {
    return c <= 0.04045f ? c / 12.92f : pow((c + 0.055f) / 1.055f, 2.4f);
}

TP_INLINE vec3 tonemap(vec3 linear, float exposureEv) {
    // NaN fails every comparison: turn it into 0 before the curve.
    vec3 x = linear * exp2(exposureEv);
    x = vec3(x.x > 0.0f ? x.x : 0.0f, x.y > 0.0f ? x.y : 0.0f, x.z > 0.0f ? x.z : 0.0f);
    vec3 t = acesFitted(x);
    return vec3(srgbEncode(t.x), srgbEncode(t.y), srgbEncode(t.z));
}

#ifndef TP_GLSL
} // namespace tp::gpu
#endif
#endif
