// --vis-edges (visbuffer/vis_settings.h): under MSAA at pixel rate with the blended fragments
// composited in compute, a GPU lights only the edges whose pixel has blended fragments one
// invocation a pixel and flattens the others (split), a CPU device every edge one invocation a
// pixel. Each pixel's surfaces are lit and composited the same way whoever runs them, so the
// image must be the same bytes; here both are forced, at the GPU's workgroup edge (16), so CI
// on lavapipe exercises the GPU's setting.
#include <gtest/gtest.h>

#include <string>

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
    // Both kinds of edge are there: edges, and blended fragments over some of them.
    EXPECT_GT(runs[1].stats.counter("edge_pixel_share", 0), 0.01);
    EXPECT_GT(runs[1].stats.counter("blended_fragments", 0), 100.0);
    // The counter names only a run with edges to split: not at --msaa-shading sample.
    s.set("msaa-shading", "sample");
    EXPECT_EQ(runOrFail(*ctx, gpuScene, "visbuffer", s).stats.counter("vis_edges_split", -1), -1.0);
    expectNoValidationMessages(*ctx);
}
