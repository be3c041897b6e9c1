// The frame runner on the default device, validation on: what it refuses before it creates
// anything on the GPU.
#include <string>

#include "core/render/renderer.h"
#include "gpu_test_util.h"

namespace tp::test {
namespace {

// A caller that skips the CLI's check (a test, a tool, the viewer's worker) and asks for a
// sample count the device lacks gets the CLI's one line from every pipeline, and no image is
// created with it: without the check the runner's targets met
// VUID-VkImageCreateInfo-samples-02258. The count is the smallest power of two the device
// does not report for colour and depth (no device reports 64, so none skips), then 3, which
// no device supports.
TEST(FrameRunner, RefusesASampleCountTheDeviceLacksWithTheCliLine) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    uint32_t lacking = 0;
    for (uint32_t n = 2; n <= 64 && lacking == 0; n *= 2)
        if (!(ctx->caps.colorSampleCounts & n)) lacking = n;
    ASSERT_NE(lacking, 0u) << ctx->info.name << " reports every sample count up to 64";
    Scene scene = makeFloorScene({});
    SceneGpu gpuScene(*ctx, scene);
    RunOptions options;
    options.warmupFrames = 0;
    options.timedFrames = 1;
    for (uint32_t samples : {lacking, 3u}) {
        const std::string expected = "--msaa " + std::to_string(samples) + ": not supported by " + ctx->info.name;
        EXPECT_EQ(checkSampleCount(*ctx, samples).error(), expected);
        for (const RendererEntry& entry : registeredRenderers()) {
            RenderSettings s;
            s.width = 32;
            s.height = 16;
            s.msaa = samples;
            Result<RunResult> run = runRenderer(*ctx, gpuScene, entry, analyzeScene(scene, samples), s, options);
            ASSERT_FALSE(run.ok()) << entry.name << " ran at " << samples << "x";
            EXPECT_EQ(run.error(), expected) << entry.name;
        }
    }
    EXPECT_TRUE(checkSampleCount(*ctx, 1).ok());
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
