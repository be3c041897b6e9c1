// The compact G-buffer encodings on the CPU (shaders/include/gbuffer_encoding.h is the code
// the shaders run): octahedral normals through RG16_SNORM and base colour through an 8-bit
// sRGB target. The bounds are derived in docs/deferred.md.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "include/gbuffer_encoding.h"

namespace tp::gpu {
namespace {

vec3 roundTripSnorm16(vec3 n) {
    vec2 e = octEncode(n);
    return octDecode(vec2(snorm16Quantize(e.x), snorm16Quantize(e.y)));
}

// 2 asin(|a - b| / 2) in double: acos of a float dot product cannot resolve angles below
// ~3e-4 rad.
double angleBetween(vec3 a, vec3 b) {
    glm::dvec3 d = glm::dvec3(a) - glm::dvec3(b);
    return 2.0 * std::asin(std::min(1.0, glm::length(d) / 2.0));
}

TEST(DeferredEncoding, OctahedralRoundTripWithinBoundOverManyDirections) {
    std::mt19937 rng(3);
    std::normal_distribution<float> g;
    // Rounding moves each coordinate of the square by at most h = 0.5/32767. On the
    // octahedron p = (u, v, 1 - |u| - |v|) that moves p by at most |(h, h, -2h)| = sqrt(6) h,
    // and normalizing divides by |p| >= 1/sqrt(3) (an octant's centre), so the angle is at
    // most sqrt(18) h = 6.47e-5 rad; the margin covers float32 rounding in decode.
    const double bound = 6.47e-5 + 1e-6;
    double worst = 0.0;
    for (int i = 0; i < 200000; ++i) {
        vec3 n = normalize(vec3(g(rng), g(rng), g(rng)));
        worst = std::max(worst, angleBetween(n, roundTripSnorm16(n)));
    }
    EXPECT_LT(worst, bound);
    EXPECT_GT(worst, 1e-6); // the test does exercise quantization
}

TEST(DeferredEncoding, AxisNormalsRoundTripExactly) {
    // Why SNORM: 0 and +-1 are exact, so the normals of floors and walls do not move.
    for (vec3 n : {vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1),
                   vec3(0, 0, -1)}) {
        vec3 r = roundTripSnorm16(n);
        EXPECT_EQ(r.x, n.x);
        EXPECT_EQ(r.y, n.y);
        EXPECT_EQ(r.z, n.z);
    }
}

TEST(DeferredEncoding, Srgb8RoundTripWithinHalfAStep) {
    // Half a step of 1/255 in the encoded domain, times the slope of the sRGB EOTF:
    // absolute error <= 0.5/255 * 2.4/1.055 = 4.46e-3 (slope is largest at 1); relative
    // error <= 0.5/255 * 2.4 / (s + 0.055) for s > 0.04045, i.e. <= 4.93 % at the knee and
    // <= 0.60 % for linear values >= 0.5 (s >= 0.735).
    float worstAbs = 0.0f, worstRelHigh = 0.0f;
    for (int i = 0; i <= 100000; ++i) {
        float c = float(i) / 100000.0f;
        float r = srgb8RoundTrip(c);
        worstAbs = std::max(worstAbs, std::abs(r - c));
        if (c >= 0.5f) worstRelHigh = std::max(worstRelHigh, std::abs(r - c) / c);
    }
    EXPECT_LT(worstAbs, 4.47e-3f);
    EXPECT_LT(worstRelHigh, 0.0060f);
    EXPECT_GT(worstAbs, 1e-3f);
}

} // namespace
} // namespace tp::gpu
