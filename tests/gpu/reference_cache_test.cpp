// The reference cache (compare/cache/reference_cache.h): a key changes with every input the
// reference's image depends on (resolution, MSAA, a reference knob, the lights, the camera, the
// pipelines' shadow rasterizer under --reference-shadows maps)
// and with none it does not (a pipeline's knob: changing it is what the cache is for); an
// entry gives back the run it stored, images bit for bit and the figures it measured.
#include <gtest/gtest.h>

#include <filesystem>

#include "compare/cache/reference_cache.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/scene/lights.h"
#include "gpu_test_util.h"

namespace tp::test {
namespace {

RenderSettings tiny() {
    RenderSettings s;
    s.width = 32;
    s.height = 18;
    return s;
}

TEST(ReferenceCache, TheKeyFollowsEveryInputOfTheReferenceAndNoOther) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(8, 3);
    SceneGpu gpu(*ctx, scene);
    const SceneFeatures f = analyzeScene(scene, 1);
    auto key = [&](const RenderSettings& s) { return cli::referenceKey(*ctx, gpu, f, s).hash; };
    const std::string base = key(tiny());
    EXPECT_EQ(key(tiny()), base) << "deterministic";
    RenderSettings s = tiny();
    s.set("tile", "8"); // a pipeline's knob: the reference does not read it
    EXPECT_EQ(key(s), base);
    s = tiny();
    s.width = 33;
    EXPECT_NE(key(s), base) << "resolution";
    s = tiny();
    s.msaa = 4;
    EXPECT_NE(key(s), base) << "MSAA";
    s = tiny();
    s.set("reference-precision", "fp32");
    EXPECT_NE(key(s), base) << "a reference knob";
    // The maps reference follows the pipelines' shadow rasterizer; shadow rays do not.
    RenderSettings shadowed = tiny();
    shadowed.shadows.count = 2;
    const std::string rays = key(shadowed);
    s = shadowed;
    s.set("shadow-raster", "compute");
    s.set("cull-geometry", "frustum");
    EXPECT_EQ(key(s), rays) << "shadow rays see no map";
    shadowed.set("reference-shadows", "maps");
    const std::string maps = key(shadowed);
    EXPECT_NE(maps, rays);
    s = shadowed;
    s.set("cull-geometry", "frustum"); // hardware maps are drawn whole
    EXPECT_EQ(key(s), maps);
    s.set("shadow-raster", "compute");
    const std::string computeMaps = key(s);
    EXPECT_NE(computeMaps, maps) << "the compute rasterizer";
    s.set("cull-geometry", "full"); // the faces are culled as by frustum
    EXPECT_EQ(key(s), computeMaps);
    std::vector<Light> lights = scene.lights;
    lights[0].intensity *= 1.0001f;
    gpu.setLights(lights);
    EXPECT_NE(key(tiny()), base) << "a light";
    Scene moved = scene;
    moved.camera.position.x += 0.001f;
    SceneGpu movedGpu(*ctx, moved);
    EXPECT_NE(cli::referenceKey(*ctx, movedGpu, f, tiny()).hash, base) << "the camera";
}

TEST(ReferenceCache, AnEntryGivesBackTheRunItStored) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(8, 3);
    SceneGpu gpu(*ctx, scene);
    const SceneFeatures f = analyzeScene(scene, 1);
    const std::string dir = ::testing::TempDir() + "/reference_cache_test";
    std::filesystem::remove_all(dir);
    cli::ReferenceCacheUse first, second;
    Result<RunResult> made = cli::runReferenceCached(*ctx, gpu, f, tiny(), {}, dir, first);
    ASSERT_TRUE(made) << made.error();
    EXPECT_TRUE(first.stored && !first.reused) << first.note;
    Result<RunResult> again = cli::runReferenceCached(*ctx, gpu, f, tiny(), {}, dir, second);
    ASSERT_TRUE(again) << again.error();
    EXPECT_TRUE(second.reused) << second.note;
    EXPECT_EQ(again->hdr.rgba, made->hdr.rgba);
    EXPECT_EQ(again->depth.r, made->depth.r);
    ASSERT_EQ(again->timings.size(), made->timings.size());
    EXPECT_EQ(again->timings[0].medianMs, made->timings[0].medianMs);
    ASSERT_EQ(again->memory.size(), made->memory.size());
    EXPECT_EQ(again->memory[0].bytes, made->memory[0].bytes);
    EXPECT_EQ(again->stats.counters, made->stats.counters);
    EXPECT_EQ(again->knobs.size(), made->knobs.size());
    expectNoValidationMessages(*ctx);
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace tp::test
