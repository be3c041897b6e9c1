// The reference on the built-in courtyard (test-sized) and on real glTF scenes.
#include <cmath>
#include <filesystem>

#include "core/scene/gltf_loader.h"
#include "core/scene/lights.h"
#include "core/scene/procedural.h"
#include "gpu_test_util.h"

namespace tp::test {
namespace {

uint64_t countNonFinite(const ImageRGBA& img) {
    uint64_t n = 0;
    for (float v : img.rgba)
        n += !std::isfinite(v);
    return n;
}

void renderAndCheck(Scene scene, uint32_t msaa) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    LightGenOptions g;
    g.count = 64;
    g.seed = 3;
    g.pointWeight = 3.0f;
    g.spotWeight = 1.0f;
    std::vector<Light> lights = generateLights(scene.bounds, g);
    scene.lights.insert(scene.lights.end(), lights.begin(), lights.end());
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings settings;
    settings.width = 96;
    settings.height = 54;
    settings.msaa = msaa;
    RunResult run = runOrFail(*ctx, gpuScene, "reference", settings);
    EXPECT_EQ(countNonFinite(run.hdr), 0u);
    double sum = 0;
    for (size_t i = 0; i < run.hdr.pixelCount(); ++i)
        sum += run.hdr.rgba[i * 4 + 1];
    EXPECT_GT(sum, 0.0) << "image is black";
    expectNoValidationMessages(*ctx);
}

TEST(BuiltinScene, ReferenceRendersCourtyardSmall) {
    Result<Scene> scene = makeBuiltinScene("courtyard-small");
    ASSERT_TRUE(scene.ok()) << scene.error();
    renderAndCheck(std::move(*scene), 1);
}

TEST(BuiltinScene, ReferenceRendersCourtyardSmallMsaa4) {
    Result<Scene> scene = makeBuiltinScene("courtyard-small");
    ASSERT_TRUE(scene.ok()) << scene.error();
    renderAndCheck(std::move(*scene), 4);
}

TEST(RealScenes, ReferenceRendersEachSharedScene) {
    const std::filesystem::path root = TP_SHARED_SCENES;
    if (!std::filesystem::exists(root)) GTEST_SKIP() << "no shared scenes at " << root;
    for (const char* rel : {"AlphaBlendModeTest/glTF/AlphaBlendModeTest.gltf",
                            "DamagedHelmet/glTF-Binary/DamagedHelmet.glb",
                            "NormalTangentMirrorTest/glTF/NormalTangentMirrorTest.gltf",
                            "VertexColorTest/glTF/VertexColorTest.gltf"}) {
        SCOPED_TRACE(rel);
        Result<Scene> scene = loadGltf((root / rel).string());
        ASSERT_TRUE(scene.ok()) << scene.error();
        renderAndCheck(std::move(*scene), 1);
    }
}

} // namespace
} // namespace tp::test
