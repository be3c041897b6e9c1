// G-buffer encodings of the deferred pipeline, shared by the shaders and the CPU tests
// (shaders/include/glsl_cpp.h rules). The hardware does the fixed-point quantization when
// a value is written to a UNORM/SNORM/sRGB target; the *Quantize helpers model it on the
// CPU so the tests can bound the round-trip error.
#ifndef TP_GBUFFER_ENCODING_H
#define TP_GBUFFER_ENCODING_H
#include "include/glsl_cpp.h"

#ifndef TP_GLSL
#include <cmath>
namespace tp::gpu {
using glm::abs;
using glm::floor;
#endif

// Octahedral normal encoding (Meyer et al. 2010; Cigolle et al. 2014): the unit sphere is
// projected onto the octahedron |x|+|y|+|z| = 1 and the lower half folded over the upper
// one, giving a square [-1,1]^2. Stored in RG16_SNORM: the square is signed, SNORM
// represents 0 and +-1 exactly (symmetric -32767..32767), so the axis-aligned normals of
// floors and walls round-trip exactly, which RG16_UNORM (no exact 0.5) cannot do.
TP_INLINE float signNotZero(float v) { return v >= 0.0f ? 1.0f : -1.0f; }

TP_INLINE vec2 octEncode(vec3 n) {
    float l1 = abs(n.x) + abs(n.y) + abs(n.z);
    vec2 p = vec2(n.x, n.y) * (1.0f / l1);
    if (n.z < 0.0f)
        p = vec2((1.0f - abs(p.y)) * signNotZero(p.x), (1.0f - abs(p.x)) * signNotZero(p.y));
    return p;
}

TP_INLINE vec3 octDecode(vec2 e) {
    vec3 n = vec3(e.x, e.y, 1.0f - abs(e.x) - abs(e.y));
    float t = clamp(-n.z, 0.0f, 1.0f);
    n.x += n.x >= 0.0f ? -t : t;
    n.y += n.y >= 0.0f ? -t : t;
    return normalize(n);
}

#ifndef TP_GLSL
// What an SNORM16 / UNORM8 target stores (round to nearest, Vulkan spec 3.9.1/3.9.2).
inline float snorm16Quantize(float v) {
    return std::round(clamp(v, -1.0f, 1.0f) * 32767.0f) / 32767.0f;
}
inline float unorm8Quantize(float v) { return std::round(clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f; }
// The sRGB transfer functions (Vulkan spec "sRGB EOTF"), for an 8-bit sRGB target.
inline float linearToSrgb(float c) {
    return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}
inline float srgbToLinear(float s) {
    return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
}
inline float srgb8RoundTrip(float c) { return srgbToLinear(unorm8Quantize(linearToSrgb(c))); }
} // namespace tp::gpu
#endif
#endif
