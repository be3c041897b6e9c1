// The blended depth bounds pass (core/passes/blended_bounds.h) draws with the
// position-only variant of scene.vert (TP_VERT_POSITION_ONLY) and reads only the position and
// the interpolated 1: it must see the same fragments at the same positions as with the whole
// interface the blended shading pass uses, so its bounds buffer is the same bit for bit.
#include <gtest/gtest.h>

#include <vector>

#include "core/gpu/frame_graph.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/readback.h"
#include "core/gpu/rendering.h"
#include "core/lightassign/tile_grid.h"
#include "core/passes/blended_bounds.h"
#include "gpu_test_util.h"

namespace tp::test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 64;

// The bounds of the courtyard-small's blended draws against its opaque depth (drawn here
// without a fragment shader, as Forward+'s prepass draws opaque surfaces).
std::vector<uint8_t> boundsOf(GpuContext& ctx, SceneGpu& scene, la::BlendedBoundsConfig config) {
    const VkSampleCountFlagBits samples = VkSampleCountFlagBits(config.samples);
    FrameGraph graph(ctx, "test", kWidth, kHeight);
    config.depth =
        graph.createImage("depth", {VK_FORMAT_D32_SFLOAT, 0, 0, samples, "opaque depth"});
    VkPipelineLayout layout = scene.createPipelineLayout();
    GraphicsPipelineDesc d;
    d.samples = samples;
    d.layout = layout;
    d.specConstants = scene.specConstants(AlphaMode::Opaque);
    VkPipeline opaque = createGraphicsPipeline(ctx, d);
    graph.addPass("opaque_depth", {{config.depth, Use::DepthAttachment}}, [&](PassContext& pc) {
        beginRendering(pc, {}, DepthTarget{config.depth});
        scene.bindSceneSet(pc.cmd, layout, VK_PIPELINE_BIND_POINT_GRAPHICS);
        scene.recordDraws(pc.cmd, layout, DrawFilter::Opaque, opaque);
        endRendering(pc);
    });
    la::BlendedBounds bounds(ctx, scene);
    ResourceHandle buffer = bounds.plan(graph, config);
    graph.exportResource("blended_bounds", buffer);
    graph.compile();
    bounds.prepare(graph);
    recordAndSubmit(ctx, graph);
    std::vector<uint8_t> bytes = readbackBuffer(ctx, graph.buffer(buffer));
    vkDestroyPipeline(ctx.device, opaque, nullptr);
    vkDestroyPipelineLayout(ctx.device, layout, nullptr);
    return bytes;
}

// The bounds at every rate the passes take them, drawn by the default pass and again with one of
// its test switches on (`variant`): the same bytes, and the comparison saw blended fragments.
// 1x and 4x; per-sample inputs (Forward+ and deferred under --msaa-shading sample, and 1x),
// once-per-pixel inputs (Forward+'s --msaa-shading pixel); per-sample shading or not.
void expectTheSameBoundsAtEveryRate(bool la::BlendedBoundsConfig::*variant) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    if (variant == &la::BlendedBoundsConfig::perFragmentAtomics && !ctx->reducesFragmentsBySubgroup())
        GTEST_SKIP() << ctx->info.name << " records the bounds per fragment only";
    Scene yard = courtyardSmallWithLights(16, 1);
    SceneGpu yardGpu(*ctx, yard);
    const la::TileGrid grid = la::makeTileGrid(kWidth, kHeight, 16);
    struct Case {
        uint32_t samples;
        bool sampleShading, inputsAtPixel;
    };
    for (Case c : {Case{1, false, false}, Case{4, true, false}, Case{4, false, true}}) {
        yardGpu.setView(kWidth, kHeight, c.samples);
        la::BlendedBoundsConfig config{grid, {}, c.samples, c.sampleShading, c.inputsAtPixel};
        std::vector<uint8_t> plain = boundsOf(*ctx, yardGpu, config);
        config.*variant = true;
        std::vector<uint8_t> other = boundsOf(*ctx, yardGpu, config);
        const std::string what = std::to_string(c.samples) + "x, " +
                                 (c.inputsAtPixel ? "pixel" : "sample") + " inputs" +
                                 (c.sampleShading ? ", per-sample shading" : "");
        ASSERT_EQ(plain.size(), size_t(grid.count()) * 8) << what;
        EXPECT_EQ(plain, other) << what;
        uint32_t any = 0;
        for (const la::TileBlendedBounds& t : la::unpackBlendedBounds(plain, grid.count()))
            any += t.any ? 1 : 0;
        EXPECT_GT(any, 0u) << what; // the comparison saw blended fragments
        EXPECT_LT(any, grid.count()) << what;
    }
    expectNoValidationMessages(*ctx);
}

TEST(BlendedBounds, PositionOnlyInterfaceRecordsTheBoundsOfTheWholeInterface) {
    expectTheSameBoundsAtEveryRate(&la::BlendedBoundsConfig::fullInterface);
}

// On a GPU the bounds are reduced per subgroup before their atomics (helpers left out); the
// result must be the bounds of one atomic pair per fragment, bit for bit, at every rate.
// A CPU device records per fragment only (GpuContext::reducesFragmentsBySubgroup): nothing to compare there.
TEST(BlendedBounds, SubgroupReductionRecordsTheBoundsOfPerFragmentAtomics) {
    expectTheSameBoundsAtEveryRate(&la::BlendedBoundsConfig::perFragmentAtomics);
}

} // namespace
} // namespace tp::test
