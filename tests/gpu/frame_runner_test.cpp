// The frame runner on the default device, validation on: what it refuses before it creates
// anything on the GPU.
#include <string>

#include "core/gpu/frame_graph.h"
#include "core/renderer/renderer.h"
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
        const std::string expected =
            "--msaa " + std::to_string(samples) + ": not supported by " + ctx->info.name;
        EXPECT_EQ(checkSampleCount(*ctx, samples).error(), expected);
        for (const RendererEntry& entry : registeredRenderers()) {
            RenderSettings s;
            s.width = 32;
            s.height = 16;
            s.msaa = samples;
            Result<RunResult> run =
                runRenderer(*ctx, gpuScene, entry, analyzeScene(scene, samples), s, options);
            ASSERT_FALSE(run.ok()) << entry.name << " ran at " << samples << "x";
            EXPECT_EQ(run.error(), expected) << entry.name;
        }
    }
    EXPECT_TRUE(checkSampleCount(*ctx, 1).ok());
    expectNoValidationMessages(*ctx);
}

// The smallest power of two the device does not report for colour and depth.
uint32_t lackingSampleCount(const GpuContext& ctx) {
    for (uint32_t n = 2; n <= 64; n *= 2)
        if (!(ctx.caps.colorSampleCounts & n)) return n;
    return 0;
}

// `triptych info` and the tests build renderers without the runner: createRenderer itself
// refuses the count with the CLI's line, before the renderer's constructor runs.
TEST(FrameRunner, CreateRendererRefusesASampleCountTheDeviceLacks) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const uint32_t lacking = lackingSampleCount(*ctx);
    ASSERT_NE(lacking, 0u) << ctx->info.name << " reports every sample count up to 64";
    Scene scene = makeFloorScene({});
    SceneGpu gpuScene(*ctx, scene);
    for (const RendererEntry& entry : registeredRenderers()) {
        RenderSettings s;
        s.width = 32;
        s.height = 16;
        s.msaa = lacking;
        try {
            createRenderer(entry, {*ctx, gpuScene, analyzeScene(scene, lacking), s});
            ADD_FAILURE() << entry.name << " was created at " << lacking << "x";
        } catch (const RendererError& e) {
            EXPECT_EQ(std::string(e.what()),
                      "--msaa " + std::to_string(lacking) + ": not supported by " + ctx->info.name)
                << entry.name;
        }
    }
    expectNoValidationMessages(*ctx);
}

// The sample counts an image may have depend on its format and usage, not only on the
// framebuffer limits checkSampleCount reads: the frame graph checks every image it is about to
// create and names the one the device cannot make, instead of meeting
// VUID-VkImageCreateInfo-samples-02258 in vkCreateImage.
TEST(FrameRunner, FrameGraphRefusesAnImageTheDeviceCannotCreate) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const uint32_t lacking = lackingSampleCount(*ctx);
    ASSERT_NE(lacking, 0u);
    FrameGraph graph(*ctx, "test", 32, 16);
    ResourceHandle hdr =
        graph.createImage("hdr_msaa", {VK_FORMAT_R32G32B32A32_SFLOAT, 0, 0,
                                       VkSampleCountFlagBits(lacking), "multisampled target"});
    graph.addPass("draw", {{hdr, Use::ColorAttachment}}, [](PassContext&) {});
    graph.exportResource("hdr", hdr);
    try {
        graph.compile();
        ADD_FAILURE() << "compiled an image of " << lacking << " samples";
    } catch (const GraphError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "image 'hdr_msaa': " + std::to_string(lacking) +
                      " samples of RGBA32_SFLOAT with transfer-src+colour attachment use: not "
                      "supported by " +
                      ctx->info.name);
    }
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
