// The reference on the default device (lavapipe in CI), validation on.
#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "gpu_test_util.h"
#include "include/light_model.h"

namespace tp::test {
namespace {

Light pointLight(glm::vec3 pos, float range, float intensity) {
    Light l;
    l.type = LightType::Point;
    l.position = pos;
    l.range = range;
    l.intensity = intensity;
    l.color = glm::vec3(1.0f, 0.9f, 0.8f);
    return l;
}

// World position of pixel (x, y) from the reverse-Z depth, as the GPU saw it.
glm::vec3 unproject(const gpu::FrameUniforms& f, uint32_t x, uint32_t y, float depth) {
    float w = float(f.viewport.x), h = float(f.viewport.y);
    glm::vec4 ndc((x + 0.5f) / w * 2.0f - 1.0f, 1.0f - (y + 0.5f) / h * 2.0f, depth, 1.0f);
    glm::vec4 p = f.invViewProj * ndc;
    return glm::vec3(p) / p.w;
}

TEST(Reference, MatchesCpuShadingOfTheFloor) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    std::vector<Light> lights = {pointLight({2, 1.5f, 2}, 6.0f, 8.0f), pointLight({-3, 2, -1}, 5.0f, 5.0f)};
    Scene scene = makeFloorScene(lights);
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings settings;
    settings.width = 96;
    settings.height = 64;
    RunResult run = runOrFail(*ctx, gpuScene, "reference", settings);
    ASSERT_EQ(run.hdr.width, 96u);
    const gpu::FrameUniforms& f = gpuScene.frame();
    int checked = 0;
    for (uint32_t y = 0; y < run.hdr.height; y += 3) {
        for (uint32_t x = 0; x < run.hdr.width; x += 3) {
            float d = run.depth.r[y * run.depth.width + x];
            if (d <= 0.0f) continue;
            glm::vec3 p = unproject(f, x, y, d);
            if (std::abs(p.y) > 1e-3f || std::abs(p.x) < 1.2f || std::abs(p.z) < 1.2f) continue; // floor only
            gpu::SurfaceSample s;
            s.position = p;
            s.normal = glm::vec3(0, 1, 0);
            s.toViewer = glm::normalize(scene.camera.position - p);
            s.baseColor = glm::vec3(0.8f);
            s.metallic = 0.0f;
            s.roughness = 1.0f;
            glm::vec3 expect = scene.ambient * s.baseColor;
            for (const Light& l : lights) expect += gpu::evalLight(toGpu(l), s, true);
            const float* got = run.hdr.at(x, y);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(got[c], expect[c], 2e-3f * expect[c] + 1e-5f) << "pixel " << x << "," << y;
            ++checked;
        }
    }
    EXPECT_GT(checked, 100);
    expectNoValidationMessages(*ctx);
}

TEST(Reference, TwoRendersAreBitIdenticalAndFinite) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = makeFloorScene({pointLight({0, 2, 2}, 5.0f, 10.0f)});
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings settings;
    settings.width = 80;
    settings.height = 48;
    settings.msaa = 4;
    RunResult a = runOrFail(*ctx, gpuScene, "reference", settings);
    RunResult b = runOrFail(*ctx, gpuScene, "reference", settings);
    ASSERT_EQ(a.hdr.rgba.size(), b.hdr.rgba.size());
    EXPECT_EQ(std::memcmp(a.hdr.rgba.data(), b.hdr.rgba.data(), a.hdr.rgba.size() * 4), 0);
    for (float v : a.hdr.rgba) ASSERT_TRUE(std::isfinite(v));
    expectNoValidationMessages(*ctx);
}

TEST(Reference, NoLightsLeavesAmbientOnly) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = makeFloorScene({});
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings settings;
    settings.width = 32;
    settings.height = 32;
    RunResult run = runOrFail(*ctx, gpuScene, "reference", settings);
    float maxValue = 0.0f;
    for (size_t i = 0; i < run.hdr.pixelCount(); ++i) maxValue = std::max(maxValue, run.hdr.rgba[i * 4]);
    EXPECT_LE(maxValue, 0.8f * 0.01f + 1e-6f); // ambient * white base colour
    EXPECT_GT(maxValue, 0.0f);
    expectNoValidationMessages(*ctx);
}

// 65,536 lights (the CLI's maximum), only the last one in reach of the floor: the result
// must equal that light alone. Lavapipe ends a shader invocation after 65,535 loop
// iterations, so a loop of one light per iteration silently dropped the last light.
TEST(Reference, ShadesTheLastOf65536Lights) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const Light lit = pointLight({0, 1.5f, 0}, 5.0f, 8.0f);
    std::vector<Light> many(65535, pointLight({500, 500, 500}, 1.0f, 1.0f));
    many.push_back(lit);
    RenderSettings settings;
    settings.width = 16;
    settings.height = 16;
    Scene oneScene = makeFloorScene({lit}), manyScene = makeFloorScene(many);
    SceneGpu oneGpu(*ctx, oneScene), manyGpu(*ctx, manyScene);
    RunResult one = runOrFail(*ctx, oneGpu, "reference", settings);
    RunResult all = runOrFail(*ctx, manyGpu, "reference", settings);
    ASSERT_EQ(one.hdr.rgba.size(), all.hdr.rgba.size());
    // The far lights add exact zeros (the falloff window is 0 past the range): same sum.
    float maxLit = 0.0f;
    for (size_t i = 0; i < one.hdr.rgba.size(); ++i) {
        ASSERT_EQ(all.hdr.rgba[i], one.hdr.rgba[i]) << "channel " << i;
        maxLit = std::max(maxLit, one.hdr.rgba[i]);
    }
    EXPECT_GT(maxLit, 0.1f); // the light does reach the floor in view
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
