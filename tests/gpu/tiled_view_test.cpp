// The tiled lighting of deferred and the visibility buffer follows a moved camera and moved
// lights in place (Renderer::updateView; core/passes/tiled_lighting.h, hybrid_blended.h). The
// lights are small enough that each covers a few tiles, so the binned candidates differ from
// view to view (checked: a stale candidate buffer would light the wrong tiles); a session
// moved there renders bit-identically what a renderer planned there renders, with no replan.
// (ViewUpdate, tests/gpu/view_update_test.cpp, uses lights that reach every tile of its
// 96x64 views, so there the candidates are the same at every view.)
#include <cstring>
#include <ostream>

#include "core/runner/render_session.h"
#include "core/scene/lights.h"
#include "core/scene/procedural.h"
#include "gpu_test_util.h"

namespace tp::test {
namespace {

struct TiledViewCase {
    std::string pipeline, bin; // --light-bin
};

// The ctest name carries the printed parameter ("# GetParam() = ..."); unprinted, gtest wrote
// the struct's raw bytes, string addresses included, so the name changed with every build and
// ctest's cost data (the order it starts tests in) never matched it.
void PrintTo(const TiledViewCase& c, std::ostream* os) {
    *os << c.pipeline << " --light-bin " << c.bin;
}

Scene courtyardWithSmallLights() {
    Result<Scene> s = makeBuiltinScene("courtyard-small");
    EXPECT_TRUE(s.ok());
    LightGenOptions o;
    o.count = 96;
    o.seed = 5;
    o.radiusMin = 1.5f;
    o.radiusMax = 3.0f;
    s->lights = generateLights(s->bounds, o);
    return std::move(*s);
}

bool identicalBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && !a.empty() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

class TiledView : public ::testing::TestWithParam<TiledViewCase> {};

TEST_P(TiledView, BinsTheLightsAgainForEachViewWithoutAReplan) {
    const TiledViewCase& c = GetParam();
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardWithSmallLights();
    RenderSettings settings;
    settings.width = 96;
    settings.height = 64;
    settings.manyViews = true;
    settings.set("light-bin", c.bin);
    // Binned, as on a CPU device: on a GPU --light-cull auto gives the visibility buffer every
    // light (up to 2,048), whose candidates no view changes (failed so on the H200).
    settings.set("light-cull", "binned");
    const RendererEntry& entry = **findRenderer(c.pipeline);
    const Camera a = scene.camera;
    Camera b = a;
    b.position = a.position + glm::vec3(-2.5f, -0.6f, 1.5f);
    b.target = a.target + glm::vec3(1.0f, 0.3f, -2.0f);
    std::vector<Light> moved = scene.lights;
    for (size_t i = 0; i < moved.size(); ++i)
        moved[i].position += glm::vec3(1.5f * std::sin(float(i)), 0.0f, 1.5f * std::cos(float(i)));

    SceneGpu gpu(*ctx, scene);
    auto session = RendererSession::create(*ctx, gpu, entry, analyzeScene(scene, 1), settings);
    ASSERT_TRUE(session.ok()) << session.error();
    RunOptions once;
    once.warmupFrames = 0;
    once.timedFrames = 1;
    auto render = [&] {
        Result<RunResult> r = (*session)->render(once);
        EXPECT_TRUE(r.ok()) << r.error();
        return r.ok() ? std::move(*r) : RunResult{};
    };
    auto fresh = [&] {
        SceneGpu planned(*ctx, scene);
        return runOrFail(*ctx, planned, c.pipeline, settings);
    };
    const RunResult atA = render();
    scene.camera = b;
    const RunResult atB = render();
    const RunResult freshB = fresh();
    gpu.setLights(moved);
    scene.lights = moved;
    const RunResult lightsMoved = render();
    const RunResult freshMoved = fresh();

    const double candA = atA.stats.counter("light_candidates"),
                 candB = atB.stats.counter("light_candidates"),
                 candMoved = lightsMoved.stats.counter("light_candidates");
    std::printf("[ tiled view ] %s --light-bin %s: light candidates %.0f at A, %.0f at B, %.0f "
                "with the lights moved\n",
                c.pipeline.c_str(), c.bin.c_str(), candA, candB, candMoved);
    EXPECT_NE(candA, candB) << "the views bin the lights differently";
    EXPECT_NE(candB, candMoved) << "the moved lights bin differently";
    EXPECT_EQ(candB, freshB.stats.counter("light_candidates"));
    EXPECT_EQ(candMoved, freshMoved.stats.counter("light_candidates"));
    EXPECT_TRUE(identicalBits(atB.hdr.rgba, freshB.hdr.rgba)) << "colour at B";
    EXPECT_TRUE(identicalBits(atB.depth.r, freshB.depth.r)) << "depth at B";
    EXPECT_TRUE(identicalBits(lightsMoved.hdr.rgba, freshMoved.hdr.rgba)) << "colour, lights moved";
    EXPECT_EQ((*session)->replans(), 0u);
    EXPECT_EQ((*session)->updates(), 2u);
    if (c.bin == "gpu") { // the views laid out by the frame, none read back
        EXPECT_EQ(lightsMoved.stats.counter("light_bin_sizing_runs", -1.0), 1.0);
    }
    expectNoValidationMessages(*ctx);
}

// --light-bin gpu lays each view out on the GPU (core/passes/light_binning.h): planned with no
// headroom (manyViews off), the lights brought close to the eye need more candidates and
// transparent-list words than the plan holds; the frame counts it, the session plans again
// (view_replans) and renders that view again - what a renderer planned there renders.
TEST_P(TiledView, PlansAgainWhenTheFrameCountsAnOverflow) {
    const TiledViewCase& c = GetParam();
    if (c.bin != "gpu") GTEST_SKIP() << "CPU binning refuses the view in updateView";
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardWithSmallLights();
    RenderSettings settings;
    settings.width = 96;
    settings.height = 64;
    settings.set("light-bin", c.bin);
    // Binned, as on a CPU device: on a GPU --light-cull auto gives the visibility buffer every
    // light (up to 2,048), whose candidates no view changes (failed so on the H200).
    settings.set("light-cull", "binned");
    const RendererEntry& entry = **findRenderer(c.pipeline);
    SceneGpu gpu(*ctx, scene);
    auto session = RendererSession::create(*ctx, gpu, entry, analyzeScene(scene, 1), settings);
    ASSERT_TRUE(session.ok()) << session.error();
    RunOptions once;
    once.warmupFrames = 0;
    once.timedFrames = 1;
    Result<RunResult> first = (*session)->render(once);
    ASSERT_TRUE(first.ok()) << first.error();
    std::vector<Light> close = scene.lights;
    for (Light& l : close)
        l.position += (scene.camera.position - l.position) * 0.6f;
    gpu.setLights(close);
    scene.lights = close;
    Result<RunResult> moved = (*session)->render(once);
    ASSERT_TRUE(moved.ok()) << moved.error();
    SceneGpu planned(*ctx, scene);
    const RunResult there = runOrFail(*ctx, planned, c.pipeline, settings);
    EXPECT_GT(there.stats.counter("light_candidates"), first->stats.counter("light_candidates"));
    EXPECT_EQ((*session)->updates(), 1u) << "followed in place first";
    EXPECT_EQ((*session)->replans(), 1u) << "the overflow counted and planned again";
    EXPECT_EQ(moved->stats.counter("view_replans"), 1.0);
    EXPECT_EQ(moved->stats.counter("light_candidates"), there.stats.counter("light_candidates"));
    EXPECT_TRUE(identicalBits(moved->hdr.rgba, there.hdr.rgba)) << "colour after the replan";
    EXPECT_EQ(moved->stats.counter("light_bin_sizing_runs", -1.0), 1.0) << "one, at the replan";
    expectNoValidationMessages(*ctx);
}

INSTANTIATE_TEST_SUITE_P(DeferredAndVisbuffer, TiledView,
                         ::testing::Values(TiledViewCase{"deferred", "cpu"},
                                           TiledViewCase{"deferred", "gpu"},
                                           TiledViewCase{"visbuffer", "cpu"},
                                           TiledViewCase{"visbuffer", "gpu"}),
                         [](const ::testing::TestParamInfo<TiledViewCase>& info) {
                             return info.param.pipeline + "_" + info.param.bin;
                         });

} // namespace
} // namespace tp::test
