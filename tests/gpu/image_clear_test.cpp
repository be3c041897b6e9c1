// ImageClear (core/passes/image_clear.h): every sample of the image set to the value, by
// compute, at 1x and 4x, for each format it has a shader for; and on a CPU device it adds no
// pass unless asked to (there the render pass's clear is the faster one). The pipelines clear
// by compute on a GPU only, so on lavapipe this is where the pass runs under validation.
#include <array>

#include "core/gpu/frame_graph.h"
#include "core/gpu/readback.h"
#include "core/gpu/vk_check.h"
#include "core/passes/image_clear.h"
#include "gpu_test_util.h"

namespace tp::test {
namespace {

constexpr uint32_t kWidth = 13, kHeight = 7; // not a multiple of the 8x8 group

// Fills `target` with 0.25 by a transfer clear first, so a pass that wrote nothing shows.
void fillPass(FrameGraph& g, ResourceHandle target) {
    g.addPass("fill", {{target, Use::TransferDst}}, [target](PassContext& pc) {
        VkClearColorValue c{{0.25f, 0.25f, 0.25f, 0.25f}};
        VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(pc.cmd, pc.image(target).image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                             &c, 1, &range);
    });
}

// The image after fill, ImageClear to `value` and (MSAA) a resolve into a single-sample image.
ImageRGBA clearAndRead(GpuContext& ctx, VkFormat format, uint32_t samples,
                       const std::array<float, 4>& value) {
    FrameGraph g(ctx, "image_clear_test", kWidth, kHeight);
    const auto count = VkSampleCountFlagBits(samples);
    ResourceHandle image = g.createImage("target", {format, 0, 0, count, "cleared"});
    ResourceHandle out = image;
    fillPass(g, image);
    ImageClear clear(ctx, true);
    VkClearColorValue v{{value[0], value[1], value[2], value[3]}};
    EXPECT_TRUE(clear.plan(g, "image_clear", image, v));
    if (samples > 1) {
        out = g.createImage("resolved", {format, 0, 0, VK_SAMPLE_COUNT_1_BIT, "its average"});
        g.addPass("resolve", {{image, Use::TransferSrc}, {out, Use::TransferDst}},
                  [image, out](PassContext& pc) {
                      VkImageResolve r{};
                      r.srcSubresource = r.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
                      r.extent = {kWidth, kHeight, 1};
                      vkCmdResolveImage(pc.cmd, pc.image(image).image,
                                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, pc.image(out).image,
                                        VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &r);
                  });
    }
    g.exportResource("hdr", out);
    g.compile();
    clear.prepare(g);
    ctx.submitAndWait([&](VkCommandBuffer cmd) { g.record(cmd, nullptr); });
    return readbackColor(ctx, g.image(out));
}

TEST(ImageClear, SetsEverySampleToTheValue) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const std::array<float, 4> value{0.0f, 0.5f, 2.0f, 1.0f}; // exact in fp16 as well
    for (VkFormat format : {VK_FORMAT_R32_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT,
                            VK_FORMAT_R16G16B16A16_SFLOAT}) {
        for (uint32_t samples : {1u, 4u}) {
            if (samples > 1 && !ctx->caps.storageImageMultisample) continue;
            const ImageRGBA img = clearAndRead(*ctx, format, samples, value);
            const uint32_t channels = format == VK_FORMAT_R32_SFLOAT ? 1 : 4;
            for (uint32_t y = 0; y < kHeight; ++y)
                for (uint32_t x = 0; x < kWidth; ++x)
                    for (uint32_t c = 0; c < channels; ++c)
                        ASSERT_EQ(img.at(x, y)[c], value[c])
                            << "format " << format << ", " << samples << "x, pixel " << x << ","
                            << y << " channel " << c;
        }
    }
    expectNoValidationMessages(*ctx);
}

TEST(ImageClear, LeavesTheClearToTheRenderPassOnACpuDevice) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    if (!ctx->isCpuDevice()) GTEST_SKIP() << "a GPU: the pass runs there";
    FrameGraph g(*ctx, "image_clear_cpu", kWidth, kHeight);
    ResourceHandle image =
        g.createImage("target", {VK_FORMAT_R32_SFLOAT, 0, 0, VK_SAMPLE_COUNT_1_BIT, "cleared"});
    ImageClear clear(*ctx);
    EXPECT_FALSE(clear.plan(g, "image_clear", image, {}));
}

} // namespace
} // namespace tp::test
