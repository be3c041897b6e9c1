// Degenerate lights through the light model the GPU runs (compiled for the CPU), as the
// stress cases spot-zero-cone and lights-range-0 feed them: they must contribute exactly
// nothing, with nothing non-finite on the way.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/gpuscene/scene_gpu.h"
#include "core/scene/stress_scenes.h"
#include "include/light_model.h"

namespace tp::test {
namespace {

using stress::build::Sequence; // the stress scenes' deterministic sequence

gpu::SurfaceSample surfaceAt(glm::vec3 p, glm::vec3 normal) {
    gpu::SurfaceSample s{};
    s.position = p;
    s.normal = normal;
    s.toViewer = normal;
    s.baseColor = glm::vec3(0.8f);
    s.metallic = 0.0f;
    s.roughness = 0.5f;
    return s;
}

// A spot at the origin and a point on its axis (rounded to fp32), facing it: the cosine to
// the axis rounds above 1 at about one such point in eight, and a zero cone must still give
// exactly 0 there. The test also checks that the sample really met cosines above 1.
TEST(LightModelDegenerate, ZeroConeLightsNothingEvenOnItsAxis) {
    for (float inner : {0.0f, 0.3f}) { // outer = inner = 0, and outer 0 below inner 0.3
        Sequence seq{7};
        int aboveOne = 0, lit = 0;
        for (int i = 0; i < 100000; ++i) {
            glm::vec3 dir =
                glm::normalize(glm::vec3(seq.next(), seq.next(), seq.next()) * 2.0f - 1.0f);
            Light spot;
            spot.type = LightType::Spot;
            spot.direction = dir;
            spot.range = 50.0f;
            spot.intensity = 1.0e3f;
            spot.innerConeAngle = inner;
            spot.outerConeAngle = 0.0f;
            const gpu::LightGpu g = toGpu(spot);
            const glm::vec3 p = g.direction * (0.5f + 20.0f * seq.next());
            const glm::vec3 toLight = -p / glm::length(p);
            aboveOne += glm::dot(g.direction, -toLight) > 1.0f;
            const glm::vec3 c = gpu::evalLight(g, surfaceAt(p, toLight), true);
            lit += c != glm::vec3(0.0f);
        }
        EXPECT_GT(aboveOne, 1000) << "the sample no longer meets cosines above 1: it tests nothing";
        EXPECT_EQ(lit, 0) << "inner " << inner << ": a zero cone lit " << lit
                          << " points on its axis";
    }
}

// Range 0 and subnormal ranges: nothing anywhere off the light's own position (where
// distance 0 < a subnormal range is inside it by the model's definition), points and spots.
TEST(LightModelDegenerate, ZeroAndSubnormalRangesLightNothing) {
    const float ranges[] = {0.0f, 1e-40f, std::numeric_limits<float>::denorm_min()};
    Sequence seq{3};
    for (float range : ranges)
        for (LightType type : {LightType::Point, LightType::Spot})
            for (int i = 0; i < 2000; ++i) {
                Light l;
                l.type = type;
                l.range = range;
                l.intensity = 1.0e6f;
                l.position = glm::vec3(seq.next(), seq.next(), seq.next()) * 4.0f - 2.0f;
                // From 1e-30 (near the light, far above subnormal distances) to 2 m away.
                const float d = std::pow(10.0f, -30.0f + 30.3f * seq.next());
                const glm::vec3 off =
                    glm::normalize(glm::vec3(seq.next(), seq.next(), seq.next()) - 0.5f) * d;
                const gpu::LightGpu g = toGpu(l);
                const glm::vec3 p = l.position + off;
                if (p == l.position) continue; // the offset rounded away: distance 0
                const glm::vec3 c = gpu::evalLight(g, surfaceAt(p, glm::normalize(-off)), true);
                EXPECT_EQ(c, glm::vec3(0.0f)) << "range " << range << " at distance " << d;
            }
}

// A range below TP_MIN_LIGHT_DISTANCE lies inside the model's distance clamp: the light is
// inert, at its own position too (distance 0 < a subnormal range lit it with 1e4 x its
// intensity); a range of exactly 1 cm still lights.
TEST(LightModelDegenerate, RangeBelowTheDistanceClampLightsNotEvenItsPosition) {
    for (float range : {1e-40f, std::numeric_limits<float>::denorm_min(), 0.005f})
        for (LightType type : {LightType::Point, LightType::Spot}) {
            Light l;
            l.type = type;
            l.range = range;
            l.intensity = 1.0e6f;
            l.position = glm::vec3(0.25f, 1.0f, -2.0f);
            const gpu::LightGpu g = toGpu(l);
            EXPECT_EQ(gpu::evalLight(g, surfaceAt(l.position, glm::vec3(0, 1, 0)), true),
                      glm::vec3(0.0f))
                << "range " << range;
        }
    Light ordinary;
    ordinary.range = TP_MIN_LIGHT_DISTANCE;
    ordinary.intensity = 1.0f;
    ordinary.position = glm::vec3(0.0f);
    EXPECT_GT(
        gpu::evalLight(toGpu(ordinary), surfaceAt(glm::vec3(0.0f), glm::vec3(0, 1, 0)), true).x,
        0.0f);
}

} // namespace
} // namespace tp::test
