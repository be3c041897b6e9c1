// Light motion (core/scene/light_motion.h): frame 0 is the start, frame k is the same computed
// alone or in sequence, lights stay inside the bounds and keep everything but their position,
// directional lights hold still, steps stay within the speed, and --light-motion's parsing.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "core/scene/light_motion.h"
#include "core/scene/lights.h"

using namespace tp;

namespace {

// The courtyard's bounds (core/scene/procedural_parts.h): 30 x 13 x 60 m.
Aabb motionBounds() {
    Aabb b;
    b.min = {-15.0f, 0.0f, -30.0f};
    b.max = {15.0f, 13.0f, 30.0f};
    return b;
}

// Generated point and spot lights, a directional one, and lights on and near the bounds'
// faces and corners (where a motion has least room).
std::vector<Light> motionLights() {
    LightGenOptions o;
    o.count = 200;
    o.seed = 7;
    o.spotWeight = 0.5f;
    std::vector<Light> lights = generateLights(motionBounds(), o);
    Light sun;
    sun.type = LightType::Directional;
    sun.position = {1.0f, 2.0f, 3.0f};
    lights.insert(lights.begin() + 3, sun);
    for (glm::vec3 p : {glm::vec3(-15.0f, 0.0f, -30.0f), glm::vec3(15.0f, 13.0f, 30.0f),
                        glm::vec3(14.99f, 6.0f, 0.0f), glm::vec3(0.0f, 0.001f, 29.9f)}) {
        Light l;
        l.position = p;
        lights.push_back(l);
    }
    return lights;
}

LightMotion motion(LightMotion::Mode mode, float speed) {
    LightMotion m;
    m.mode = mode;
    m.speed = speed;
    m.seed = 42;
    return m;
}

const LightMotion::Mode kMovingModes[2] = {LightMotion::Mode::Orbit, LightMotion::Mode::Drift};

void expectMotionRefused(const std::string& text, const std::string& expected) {
    Result<LightMotion> m = parseLightMotion(text);
    ASSERT_FALSE(m.ok()) << text;
    EXPECT_EQ(m.error(), expected);
}

} // namespace

TEST(LightMotion, FrameZeroIsTheStart) {
    const std::vector<Light> start = motionLights();
    for (LightMotion::Mode mode : kMovingModes) {
        const std::vector<Light> moved = moveLights(start, motion(mode, 0.3f), motionBounds(), 0);
        ASSERT_EQ(moved.size(), start.size());
        for (size_t i = 0; i < start.size(); ++i)
            EXPECT_EQ(moved[i].position, start[i].position) << i;
    }
}

TEST(LightMotion, AFrameAloneEqualsTheFrameInSequence) {
    const std::vector<Light> start = motionLights();
    for (LightMotion::Mode mode : kMovingModes) {
        const LightMotion m = motion(mode, 0.2f);
        // In sequence from a plan, as a run keeps it; alone through moveLights.
        const LightMotionPlan plan(start, m, motionBounds());
        std::vector<std::vector<Light>> sequence;
        for (uint32_t f = 0; f < 60; ++f)
            sequence.push_back(plan.at(f));
        for (uint32_t f : {59u, 1u, 37u}) {
            const std::vector<Light> alone = moveLights(start, m, motionBounds(), f);
            for (size_t i = 0; i < start.size(); ++i)
                ASSERT_EQ(alone[i].position, sequence[f][i].position) << f << " " << i;
        }
        // A light's motion is its own: the first lights move alike without the others.
        const std::vector<Light> fewer(start.begin(), start.begin() + 10);
        const std::vector<Light> part = moveLights(fewer, m, motionBounds(), 37);
        for (size_t i = 0; i < fewer.size(); ++i)
            EXPECT_EQ(part[i].position, sequence[37][i].position) << i;
        // Another seed, another motion.
        LightMotion other = m;
        other.seed = 43;
        EXPECT_NE(moveLights(start, other, motionBounds(), 37)[0].position,
                  sequence[37][0].position);
    }
}

TEST(LightMotion, KeepsBoundsCountTypesAndAllButPosition) {
    const std::vector<Light> start = motionLights();
    const Aabb bounds = motionBounds();
    for (LightMotion::Mode mode : kMovingModes) {
        size_t moved = 0;
        for (uint32_t f = 0; f < 3000; f += 7) {
            const std::vector<Light> lights = moveLights(start, motion(mode, 0.5f), bounds, f);
            ASSERT_EQ(lights.size(), start.size());
            for (size_t i = 0; i < start.size(); ++i) {
                const Light &a = start[i], &b = lights[i];
                ASSERT_EQ(a.type, b.type);
                ASSERT_EQ(a.color, b.color);
                ASSERT_EQ(a.intensity, b.intensity);
                ASSERT_EQ(a.range, b.range);
                ASSERT_EQ(a.direction, b.direction);
                ASSERT_EQ(a.innerConeAngle, b.innerConeAngle);
                ASSERT_EQ(a.outerConeAngle, b.outerConeAngle);
                if (a.type == LightType::Directional) {
                    ASSERT_EQ(a.position, b.position);
                }
                ASSERT_TRUE(glm::all(glm::greaterThanEqual(b.position, bounds.min)) &&
                            glm::all(glm::lessThanEqual(b.position, bounds.max)))
                    << "frame " << f << " light " << i;
                if (mode == LightMotion::Mode::Orbit) {
                    ASSERT_EQ(a.position.y, b.position.y);
                }
                moved += a.position != b.position;
            }
        }
        // Every point and spot light away from the corners moves (the directional one and
        // the two in corners with no room may not).
        EXPECT_GT(moved, (start.size() - 3) * 400);
    }
}

TEST(LightMotion, StepsStayWithinTheSpeed) {
    const std::vector<Light> start = motionLights();
    const float speed = 0.1f;
    for (LightMotion::Mode mode : kMovingModes) {
        std::vector<Light> before = start;
        float longest = 0.0f;
        for (uint32_t f = 1; f < 400; ++f) {
            const std::vector<Light> now =
                moveLights(start, motion(mode, speed), motionBounds(), f);
            for (size_t i = 0; i < start.size(); ++i)
                longest = std::max(longest, glm::length(now[i].position - before[i].position));
            before = now;
        }
        // Float rounding of coordinates up to 30 m: a few 1e-6 m.
        EXPECT_LE(longest, speed + 1e-5f);
        // Orbits run at the speed (a chord of a 0.1 m arc on a circle of 0.2 m or more).
        if (mode == LightMotion::Mode::Orbit) {
            EXPECT_GT(longest, 0.95f * speed);
        }
    }
}

TEST(LightMotion, ParsesModeAndSpeed) {
    Result<LightMotion> m = parseLightMotion("orbit");
    ASSERT_TRUE(m.ok()) << m.error();
    EXPECT_EQ(m->mode, LightMotion::Mode::Orbit);
    EXPECT_EQ(m->speed, kDefaultLightSpeed);
    m = parseLightMotion("drift:0.25");
    ASSERT_TRUE(m.ok()) << m.error();
    EXPECT_EQ(m->mode, LightMotion::Mode::Drift);
    EXPECT_EQ(m->speed, 0.25f);
    EXPECT_EQ(lightMotionToString(*m), "drift:0.25");
    m = parseLightMotion("none");
    ASSERT_TRUE(m.ok()) << m.error();
    EXPECT_EQ(m->mode, LightMotion::Mode::None);
    EXPECT_EQ(lightMotionToString(*m), "none");
    expectMotionRefused("wobble", "--light-motion: unknown mode \"wobble\" (valid: none, orbit, "
                                  "drift)");
    expectMotionRefused("none:1", "--light-motion: \"none\" takes no speed (got \"none:1\")");
    for (const char* speed : {"", "0", "-1", "abc", "1e7", "nan", "0.5x"})
        expectMotionRefused(std::string("orbit:") + speed,
                            std::string("--light-motion: speed \"") + speed +
                                "\" must be a number > 0 and at most 1e6 (scene units per frame)");
}

// What the motion costs per frame at the benchmark's 1,024 lights (docs/camera_paths.md): a
// run keeps a LightMotionPlan and asks it for each view's lights on the CPU. Printed, not asserted
// (machines differ).
TEST(LightMotion, CostAt1024Lights) {
    LightGenOptions o;
    o.count = 1024;
    o.seed = 3;
    const std::vector<Light> start = generateLights(motionBounds(), o);
    for (LightMotion::Mode mode : kMovingModes) {
        const auto begin = std::chrono::steady_clock::now();
        const LightMotionPlan plan(start, motion(mode, 0.05f), motionBounds());
        size_t checksum = 0;
        for (uint32_t f = 1; f <= 120; ++f)
            checksum += plan.at(f).size();
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin)
                .count();
        EXPECT_EQ(checksum, 120u * 1024u);
        std::printf("[ timing ] %s, 1024 lights: %.3f ms a frame\n",
                    mode == LightMotion::Mode::Orbit ? "orbit" : "drift", ms / 120.0);
    }
}
