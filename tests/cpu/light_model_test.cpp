// The light model the GPU runs, compiled for the CPU through shaders/include/glsl_cpp.h.
#include <gtest/gtest.h>

#include "include/light_model.h"

using namespace tp::gpu;

TEST(LightModel, WindowReachesZeroAtRange) {
    for (float range : {0.5f, 1.0f, 7.0f, 1000.0f}) {
        EXPECT_EQ(rangeWindow(range, range), 0.0f);
        EXPECT_EQ(rangeWindow(range * 1.5f, range), 0.0f);
        EXPECT_EQ(distanceAttenuation(range, range), 0.0f);
        EXPECT_GT(distanceAttenuation(range * 0.999f, range), 0.0f);
        EXPECT_EQ(rangeWindow(0.0f, range), 1.0f);
    }
}

TEST(LightModel, FalloffIsContinuousAndMonotonic) {
    const float range = 5.0f;
    float prev = distanceAttenuation(0.0f, range);
    for (int i = 1; i <= 5000; ++i) {
        float d = range * float(i) / 5000.0f;
        float a = distanceAttenuation(d, range);
        EXPECT_LE(a, prev) << "d=" << d;
        prev = a;
    }
    EXPECT_EQ(prev, 0.0f);
    // Continuous at the two seams: the distance clamp and the range.
    const float m = TP_MIN_LIGHT_DISTANCE;
    float below = distanceAttenuation(m * (1.0f - 1e-5f), range);
    float above = distanceAttenuation(m * (1.0f + 1e-5f), range);
    EXPECT_NEAR(above / below, 1.0f, 1e-4f);
    float nearEnd = distanceAttenuation(range * (1.0f - 1e-3f), range);
    EXPECT_LT(nearEnd, 1e-4f * distanceAttenuation(range * 0.5f, range));
}

TEST(LightModel, DistanceClampKeepsTouchingLightFinite) {
    float a0 = distanceAttenuation(0.0f, 1.0f);
    EXPECT_TRUE(std::isfinite(a0));
    EXPECT_NEAR(a0, 1.0f / (TP_MIN_LIGHT_DISTANCE * TP_MIN_LIGHT_DISTANCE), 1.0f);
}

namespace {

// A white surface at the origin facing +z, seen from straight above.
SurfaceSample whiteFacingUp(float metallic, float roughness) {
    SurfaceSample s;
    s.position = vec3(0.0f);
    s.normal = vec3(0, 0, 1);
    s.toViewer = vec3(0, 0, 1);
    s.baseColor = vec3(1.0f);
    s.metallic = metallic;
    s.roughness = roughness;
    return s;
}

} // namespace

TEST(LightModel, BrdfFiniteAtRoughnessZeroAndGrazing) {
    SurfaceSample s = whiteFacingUp(1.0f, 0.0f);
    vec3 spike = brdfCos(s, vec3(0, 0, 1));
    EXPECT_TRUE(std::isfinite(spike.x));
    EXPECT_GT(spike.x, 0.0f);
    s.toViewer = normalize(vec3(1, 0, 1e-9f));
    vec3 grazing = brdfCos(s, normalize(vec3(-1, 0, 1e-9f)));
    EXPECT_TRUE(std::isfinite(grazing.x));
    EXPECT_EQ(brdfCos(s, vec3(0, 0, -1)).x, 0.0f); // below the horizon
}

TEST(LightModel, LambertEnergyOfWhiteDielectricIsBelowOne) {
    // Monte-Carlo-free check: integrate brdfCos over the hemisphere on a grid.
    SurfaceSample s = whiteFacingUp(0.0f, 1.0f);
    double sum = 0.0;
    const int n = 256;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < 4 * n; ++j) {
            float theta = (i + 0.5f) / n * (TP_PI / 2);
            float phi = (j + 0.5f) / (4 * n) * 2 * TP_PI;
            vec3 l(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                   std::cos(theta));
            sum += brdfCos(s, l).x * std::sin(theta) * (TP_PI / 2 / n) * (2 * TP_PI / (4 * n));
        }
    EXPECT_GT(sum, 0.85);
    EXPECT_LT(sum, 1.05);
}

TEST(LightModel, SpotConeFalloff) {
    float cosOuter = std::cos(0.5f), cosInner = std::cos(0.3f);
    float scale = 1.0f / (cosInner - cosOuter), offset = -cosOuter * scale;
    vec3 dir(0, -1, 0);
    EXPECT_EQ(spotAttenuation(vec3(0, 1, 0), dir, scale, offset), 1.0f); // on axis
    vec3 outside = normalize(vec3(std::sin(0.6f), std::cos(0.6f), 0));
    EXPECT_EQ(spotAttenuation(outside, dir, scale, offset), 0.0f);
}
