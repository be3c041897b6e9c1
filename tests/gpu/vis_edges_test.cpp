// --vis-edges (visbuffer/vis_settings.h): under MSAA at pixel rate with the blended fragments
// composited in compute, a GPU lights only the edges whose pixel has blended fragments one
// invocation a pixel and flattens the others (split), a CPU device every edge one invocation a
// pixel. Each pixel's surfaces are lit and composited the same way whoever runs them, so the
// image must be the same bytes; here both are forced, at the GPU's workgroup edge (16), so CI
// on lavapipe exercises the GPU's setting.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "core/renderer/renderer.h"
#include "core/runner/frame_runner.h"
#include "gpu_test_util.h"

using namespace tp;
using namespace tp::test;

TEST(VisEdges, SplitGivesTheImageOfPixel) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(128, 5); // blended draws: edges with and without lists
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings s;
    s.width = 96;
    s.height = 64;
    s.msaa = 4;
    s.set("tile-group", "16");
    RunResult runs[2];
    for (int split = 0; split < 2; ++split) {
        s.set("vis-edges", split ? "split" : "pixel");
        runs[split] = runOrFail(*ctx, gpuScene, "visbuffer", s);
        EXPECT_EQ(runs[split].stats.counter("vis_edges_split", -1), double(split));
    }
    EXPECT_EQ(runs[0].hdr.rgba, runs[1].hdr.rgba);
    // Both kinds of edge are there: edge pixels (--debug's mask) with a blended list and without.
    RenderSettings debug = s;
    debug.debug = true;
    const RunResult shown = runOrFail(*ctx, gpuScene, "visbuffer", debug);
    const ImageRGBA* edges = debugImageOf(shown, "edge_mask");
    const std::vector<std::vector<uint8_t>> heads =
        exportedBuffers(*ctx, gpuScene, "visbuffer", debug, {"blended_heads"});
    ASSERT_NE(edges, nullptr);
    ASSERT_GE(heads[0].size(), edges->pixelCount() * sizeof(uint32_t));
    size_t composited = 0, flat = 0;
    for (size_t i = 0; i < edges->pixelCount(); ++i) {
        if (edges->rgba[i * 4] <= 0.5f) continue;
        uint32_t head = 0;
        std::memcpy(&head, heads[0].data() + i * sizeof(uint32_t), sizeof(head));
        (head != 0 ? composited : flat) += 1;
    }
    EXPECT_GT(composited, 0u) << "edge pixels with blended fragments";
    EXPECT_GT(flat, composited) << "and more without";
    // The counter names only a run with edges to split: not at --msaa-shading sample.
    s.set("msaa-shading", "sample");
    EXPECT_EQ(runOrFail(*ctx, gpuScene, "visbuffer", s).stats.counter("vis_edges_split", -1), -1.0);
    expectNoValidationMessages(*ctx);
}
