// The shadow plan (core/passes/shadow_planner.h): which lights cast shadows, their faces, the
// budget and the atlas packing, and the matrices the maps are rendered and sampled with.
#include <gtest/gtest.h>

#include <set>

#include "core/camera/camera.h"
#include "core/cli/options.h"
#include "core/cli/shadow_option.h"
#include "core/passes/shadow_planner.h"

using namespace tp;

namespace {

constexpr uint32_t kShW = 320, kShH = 180;

gpu::FrameUniforms shFrame() {
    gpu::FrameUniforms f{};
    f.view = glm::mat4(1.0f); // at the origin, looking down -z
    f.proj = reverseZPerspective(1.0f, float(kShW) / float(kShH), 0.1f, 100.0f);
    f.viewProj = f.proj * f.view;
    f.viewport = glm::uvec4(kShW, kShH, 0, 1);
    return f;
}

gpu::LightGpu shLight(uint32_t type, glm::vec3 p, float range, float outer = 0.5f) {
    gpu::LightGpu l{};
    l.type = type;
    l.position = p;
    l.range = range;
    l.direction = glm::vec3(0, 0, -1);
    l.spotScale = 1.0f / std::max(1e-4f, std::cos(outer * 0.5f) - std::cos(outer));
    l.spotOffset = -std::cos(outer) * l.spotScale;
    return l;
}

ShadowSettings shCount(uint32_t n, uint32_t budgetMb = 256) {
    ShadowSettings s;
    s.count = n;
    s.budgetMb = budgetMb;
    return s;
}

} // namespace

TEST(ShadowPlan, NoneIsEmpty) {
    const auto lights = std::vector{shLight(TP_LIGHT_POINT, {0, 0, -5}, 2)};
    EXPECT_TRUE(planShadows(lights, shFrame(), kShW, kShH, ShadowSettings{}, 16384).empty());
}

TEST(ShadowPlan, PicksTheMostInfluentialAndSkipsDirectionalAndUnseen) {
    std::vector<gpu::LightGpu> lights = {
        shLight(TP_LIGHT_POINT, {0, 0, -20}, 1),   // far: small on screen
        shLight(TP_LIGHT_DIRECTIONAL, {0, 0, 0}, 1),
        shLight(TP_LIGHT_POINT, {0, 0, -4}, 2),    // near: large
        shLight(TP_LIGHT_POINT, {0, 0, 30}, 2),    // behind the camera: unseen
        shLight(TP_LIGHT_SPOT, {1, 0, -6}, 2)};
    const ShadowPlan two = planShadows(lights, shFrame(), kShW, kShH, shCount(2), 16384);
    ASSERT_EQ(two.lights.size(), 2u);
    EXPECT_EQ(two.lights[0].light, 2u);
    EXPECT_GE(two.lights[0].influence, two.lights[1].influence);
    ShadowSettings all;
    all.all = true;
    const ShadowPlan every = planShadows(lights, shFrame(), kShW, kShH, all, 16384);
    std::set<uint32_t> chosen;
    for (const ShadowLight& l : every.lights) chosen.insert(l.light);
    EXPECT_EQ(chosen, (std::set<uint32_t>{0, 2, 4}));
    for (const ShadowLight& l : every.lights)
        EXPECT_EQ(l.faceCount, lights[l.light].type == TP_LIGHT_SPOT ? 1u : 6u);
}

TEST(ShadowPlan, FacesTileTheAtlasWithoutOverlap) {
    std::vector<gpu::LightGpu> lights;
    for (int i = 0; i < 40; ++i)
        lights.push_back(shLight(i % 3 ? TP_LIGHT_POINT : TP_LIGHT_SPOT,
                               {float(i % 8) - 4.0f, float(i / 8) - 2.0f, -3.0f - float(i % 5)},
                               0.5f + 0.1f * float(i % 7)));
    ShadowSettings all;
    all.all = true;
    const ShadowPlan p = planShadows(lights, shFrame(), kShW, kShH, all, 16384);
    ASSERT_FALSE(p.empty());
    std::vector<uint8_t> used(size_t(p.atlasWidth) * p.atlasHeight, 0);
    for (const gpu::ShadowFace& f : p.faces) {
        ASSERT_LE(f.atlas.x + f.atlas.z, p.atlasWidth);
        ASSERT_LE(f.atlas.y + f.atlas.z, p.atlasHeight);
        for (uint32_t y = f.atlas.y; y < f.atlas.y + f.atlas.z; ++y)
            for (uint32_t x = f.atlas.x; x < f.atlas.x + f.atlas.z; ++x)
                ASSERT_EQ(used[size_t(y) * p.atlasWidth + x]++, 0) << "faces overlap at " << x << "," << y;
        EXPECT_LE(f.local.x + f.local.z, p.localWidth);
        EXPECT_LE(f.local.y + f.local.z, p.localHeight);
    }
    EXPECT_LE(p.faceTexels(), p.atlasBytes() / 4);
    EXPECT_GT(p.faceTexels() * 2, p.atlasBytes() / 4); // a power-of-two atlas at most half empty
}

TEST(ShadowPlan, TheBudgetHalvesTheLargestMapsAndRefusesWhatCannotFit) {
    std::vector<gpu::LightGpu> lights;
    for (int i = 0; i < 8; ++i) lights.push_back(shLight(TP_LIGHT_POINT, {float(i) - 4.0f, 0, -2}, 3));
    const ShadowPlan roomy = planShadows(lights, shFrame(), 1920, 1080, shCount(8, 1024), 16384);
    const ShadowPlan tight = planShadows(lights, shFrame(), 1920, 1080, shCount(8, 1), 16384);
    EXPECT_LE(tight.atlasBytes(), 1u << 20);
    EXPECT_LT(tight.atlasBytes(), roomy.atlasBytes());
    // 8 cube lights at 16x16 need 48 KiB: fits 1 MB. 4096 cube lights at 16x16 need 24 MiB.
    std::vector<gpu::LightGpu> many;
    for (int i = 0; i < 4096; ++i)
        many.push_back(shLight(TP_LIGHT_POINT, {float(i % 64) * 0.1f - 3.2f, float(i / 64) * 0.05f - 1.6f, -4}, 0.5f));
    ShadowSettings all;
    all.all = true;
    all.budgetMb = 8;
    EXPECT_THROW(planShadows(many, shFrame(), kShW, kShH, all, 16384), ShadowError);
}

TEST(ShadowPlan, AFaceProjectsDistanceAsNearOverDepth) {
    const auto lights = std::vector{shLight(TP_LIGHT_POINT, {0, 0, -5}, 4)};
    const ShadowPlan p = planShadows(lights, shFrame(), kShW, kShH, shCount(1), 16384);
    ASSERT_EQ(p.faces.size(), 6u);
    // +X face: a point 2 m along +x and a little off axis lands inside, at depth near / 2.
    const glm::vec4 clip = p.faces[0].lightProj * glm::vec4(2.0f, 0.3f, -0.2f, 1.0f);
    EXPECT_NEAR(clip.w, 2.0f, 1e-5f);
    EXPECT_NEAR(clip.z / clip.w, kShadowNear / 2.0f, 1e-9f);
    EXPECT_LT(std::abs(clip.x / clip.w), 1.0f);
    EXPECT_LT(std::abs(clip.y / clip.w), 1.0f);
    // Each cube face sees its own axis.
    const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int f = 0; f < 6; ++f) {
        const glm::vec4 c = p.faces[f].lightProj * glm::vec4(axes[f] * 3.0f, 1.0f);
        EXPECT_NEAR(c.w, 3.0f, 1e-5f) << f;
        EXPECT_NEAR(c.x / c.w, 0.0f, 1e-6f) << f;
    }
}

// --shadows is parsed at the command line's boundary (core/cli/shadow_option.h).
TEST(ShadowOption, ParsesWithOneLineErrors) {
    EXPECT_FALSE(parseShadowCount("none").enabled());
    EXPECT_TRUE(parseShadowCount("all").all);
    EXPECT_EQ(parseShadowCount("16").count, 16u);
    for (const char* bad : {"", "0", "-3", "x", "12x", "65537"})
        EXPECT_THROW(parseShadowCount(bad), cli::UsageError) << bad;
}
