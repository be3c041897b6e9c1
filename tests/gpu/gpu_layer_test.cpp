// The GPU layer itself: validation really reports, the frame graph culls and allocates from
// declarations, the ledger holds what was allocated, the profiler measures.
#include <cstring>

#include "core/gpu/frame_graph.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/profiler.h"
#include "core/gpu/readback.h"
#include "core/gpu/shader_reflection.h"
#include "core/gpu/vk_check.h"
#include "core/image/image_io.h"
#include "deferred/deferred_shared.h"
#include "gpu_test_util.h"
#include "include/shared.h"

namespace tp::test {
namespace {

TEST(GpuLayer, ValidationMessagesAreCaught) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    // A buffer of size 0 is invalid usage: the layer must report it, and we must see it.
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = 0;
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    VkBuffer buffer = VK_NULL_HANDLE;
    vkCreateBuffer(ctx->device, &info, nullptr, &buffer);
    if (buffer) vkDestroyBuffer(ctx->device, buffer, nullptr);
    EXPECT_FALSE(ctx->validationMessages().empty());
}

// Clears an image with a transfer command: the smallest pass that writes something.
void clearPass(FrameGraph& g, const std::string& name, ResourceHandle target, float value) {
    g.addPass(name, {{target, Use::TransferDst}}, [target, value](PassContext& pc) {
        VkClearColorValue c{{value, value, value, 1.0f}};
        VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(pc.cmd, pc.image(target).image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                             &c, 1, &range);
    });
}

TEST(GpuLayer, FrameGraphCullsUnusedPassesAndLedgersTransients) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    {
        FrameGraph g(*ctx, "graph_test", 16, 8);
        ResourceHandle a = g.createImage(
            "a", {VK_FORMAT_R32G32B32A32_SFLOAT, 0, 0, VK_SAMPLE_COUNT_1_BIT, "kept"});
        ResourceHandle unused = g.createImage("unused", {VK_FORMAT_R16G16B16A16_SFLOAT, 0, 0,
                                                         VK_SAMPLE_COUNT_1_BIT, "nobody reads it"});
        clearPass(g, "write_a", a, 0.5f);
        clearPass(g, "write_unused", unused, 1.0f);
        clearPass(g, "write_a_again", a, 0.25f); // WAW on the same image: needs a barrier
        g.exportResource("hdr", a);
        g.compile();
        EXPECT_EQ(g.livePasses(), (std::vector<std::string>{"write_a", "write_a_again"}));
        EXPECT_EQ(g.culledPasses(), (std::vector<std::string>{"write_unused"}));
        EXPECT_TRUE(g.isAllocated(a));
        EXPECT_FALSE(g.isAllocated(unused)); // culled pass: no memory spent
        std::vector<LedgerEntry> entries = ctx->ledger.entriesOf("graph_test");
        ASSERT_EQ(entries.size(), 1u);
        EXPECT_EQ(entries[0].tag.name, "a");
        EXPECT_EQ(entries[0].tag.pass, "write_a");
        EXPECT_EQ(entries[0].requestedBytes, 16u * 8u * 16u);
        EXPECT_GE(entries[0].bytes, entries[0].requestedBytes);

        GpuProfiler profiler(*ctx, 8);
        VkCommandBuffer cmd = ctx->allocateCommandBuffer();
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
        profiler.beginFrame(cmd);
        g.record(cmd, &profiler);
        profiler.endFrame(cmd);
        VK_CHECK(vkEndCommandBuffer(cmd));
        for (int i = 0; i < 3; ++i) { // resubmitting the same recording must stay valid
            ctx->submitAndWait(cmd);
            profiler.collect();
        }
        ctx->freeCommandBuffer(cmd);
        std::vector<TimingStats> t = profiler.stats();
        ASSERT_EQ(t.size(), 3u);
        EXPECT_EQ(t[0].name, "frame");
        EXPECT_EQ(t[1].name, "write_a");
        EXPECT_EQ(t[0].frames, 3u);
        EXPECT_GE(t[0].maxMs, t[0].minMs);
        ImageRGBA img = readbackColor(*ctx, g.image(a));
        EXPECT_EQ(img.at(3, 4)[0], 0.25f);
    }
    EXPECT_TRUE(ctx->ledger.entriesOf("graph_test").empty()); // freed with the graph
    expectNoValidationMessages(*ctx);
}

TEST(GpuLayer, FrameGraphMakesPassSetsFromUsesAndPipelinesCheckThemAgainstShaders) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    {
        FrameGraph g(*ctx, "set_test", 16, 8);
        ResourceHandle lists = g.createBuffer("lists", 256, "read through set 1");
        ResourceHandle hdr = g.createImage(
            "hdr", {VK_FORMAT_R32G32B32A32_SFLOAT, 0, 0, VK_SAMPLE_COUNT_1_BIT, "out"});
        g.addPass("fill", {{lists, Use::TransferDst}}, [](PassContext&) {});
        g.addPass(
            "transparent_forward",
            {{lists, Use::StorageRead, TP_BF_BINDING_LISTS}, {hdr, Use::ColorAttachment}},
            [](PassContext&) {});
        g.exportResource("hdr", hdr);
        g.compile();
        EXPECT_THROW(g.addPass("late", {{hdr, Use::Sampled}}, [](PassContext&) {}), GraphError);

        PassSet set = g.createPassSet("transparent_forward");
        ASSERT_EQ(set.bindings.size(), 1u);
        EXPECT_EQ(set.bindings[0].binding, uint32_t(TP_BF_BINDING_LISTS));
        EXPECT_EQ(set.bindings[0].type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
        // The wrong shader for this set: refused before Vulkan sees it, naming pass and shader.
        try {
            createComputePipeline(*ctx, "deferred_tiled_lists_m0_comp", {}, VK_NULL_HANDLE, &set);
            ADD_FAILURE() << "no BindingMismatch";
        } catch (const BindingMismatch& e) {
            EXPECT_NE(std::string(e.what()).find("pass 'transparent_forward'"), std::string::npos)
                << e.what();
            EXPECT_NE(std::string(e.what()).find("deferred_tiled_lists_m0_comp"), std::string::npos)
                << e.what();
        }
        destroyPassSet(*ctx, set);
    }
    expectNoValidationMessages(*ctx);
}

TEST(GpuLayer, ExrWrittenEqualsTheReadback) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Light l;
    l.position = {1, 2, 1};
    l.range = 6.0f;
    l.intensity = 5.0f;
    Scene scene = makeFloorScene({l});
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings settings;
    settings.width = 40;
    settings.height = 24;
    RunResult run = runOrFail(*ctx, gpuScene, "reference", settings);
    std::string path = ::testing::TempDir() + "/tp_readback.exr";
    ASSERT_TRUE(writeExr(path, run.hdr, ExrPixelType::Float).ok());
    Result<ImageRGBA> back = readExr(path);
    ASSERT_TRUE(back.ok()) << back.error();
    ASSERT_EQ(back->rgba.size(), run.hdr.rgba.size());
    EXPECT_EQ(std::memcmp(back->rgba.data(), run.hdr.rgba.data(), run.hdr.rgba.size() * 4), 0);
    // Per-pass timings and the ledger came back with the run.
    ASSERT_GE(run.timings.size(), 2u);
    EXPECT_EQ(run.timings[1].name, "reference_shading");
    EXPECT_FALSE(run.memory.empty());
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
