// Forward+ planned once, moved to other views (forwardplus/view_bins.h; the contract's step 6):
// a view whose lists fit the planned room is followed in place; a view that needs more slots
// than the plan holds is refused by updateView (CPU binning) or counted by the frame (GPU
// binning: Renderer::overflowed, rendered again) and planned again, counted (view_replans) -
// never silent, never a cut list - and renders what a renderer planned there renders.
// view_update_test.cpp checks the ordinary views of every configuration with headroom; here
// the lists are sized exactly (RenderSettings::manyViews off), so the room is the first view's.
#include <cstring>
#include <map>
#include <string>

#include "core/lightassign/light_bins.h"
#include "core/lightassign/light_classes.h"
#include "core/lightassign/tile_grid.h"
#include "core/runner/render_session.h"
#include "gpu_test_util.h"

namespace tp::test {
namespace {

constexpr uint32_t kW = 96, kH = 64;

// The slots a view's compact lists need: what Forward+ bins for it (the CPU binning).
uint64_t slotsAt(GpuContext& ctx, Scene scene, const Camera& cam, const std::vector<Light>& lights) {
    scene.camera = cam;
    scene.lights = lights;
    SceneGpu gpu(ctx, scene);
    gpu.setView(kW, kH, 1);
    const gpu::FrameUniforms& f = gpu.shadingFrame();
    const std::vector<uint32_t> local = la::classifyLights(gpu.shadingLights()).local;
    return la::binLights(la::makeTileGrid(kW, kH, 16), f.view, f.proj, gpu.shadingLights(), local,
                         false)
        .slots;
}

// Every light moved `share` of the way to the eye: larger on screen, more tiles each.
std::vector<Light> towards(std::vector<Light> lights, const glm::vec3& eye, float share) {
    for (Light& l : lights)
        l.position += (eye - l.position) * share;
    return lights;
}

Camera scaled(const Camera& a, float arm) {
    Camera c = a;
    c.position = a.target + (a.position - a.target) * arm;
    return c;
}

RunResult render(RendererSession& session) {
    RunOptions once;
    once.warmupFrames = 0;
    once.timedFrames = 1;
    Result<RunResult> r = session.render(once);
    EXPECT_TRUE(r.ok()) << r.error();
    return r.ok() ? std::move(*r) : RunResult{};
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && !a.empty() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// --light-bin cpu and gpu (tiled: the frame lays the view out and counts an overflow, read after
// the view's frames), clustered (the mask rows' room too).
class ForwardPlusViews : public ::testing::TestWithParam<std::map<std::string, std::string>> {};

// What a renderer planned at the scene's current view renders, bit for bit.
void expectPlannedThere(GpuContext& ctx, Scene& scene, const RendererEntry& entry,
                        const RenderSettings& settings, const RunResult& got, const char* what) {
    SceneGpu fresh(ctx, scene);
    auto there = RendererSession::create(ctx, fresh, entry, analyzeScene(scene, 1), settings);
    ASSERT_TRUE(there.ok()) << there.error();
    const RunResult want = render(**there);
    EXPECT_TRUE(sameBits(got.hdr.rgba, want.hdr.rgba)) << what << ": colour differs";
    EXPECT_TRUE(sameBits(got.depth.r, want.depth.r)) << what << ": depth differs";
    // The lists themselves (the image holds only the lights that reach a pixel).
    EXPECT_EQ(got.stats.counter("lights_kept"), want.stats.counter("lights_kept")) << what;
    EXPECT_EQ(got.stats.counter("lights_tested"), want.stats.counter("lights_tested")) << what;
}

TEST_P(ForwardPlusViews, FollowsInPlaceWithinTheRoomAndPlansAgainPastIt) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(64, 11);
    const Camera a = scene.camera, far = scaled(a, 1.6f);
    const std::vector<Light> lights = scene.lights, close = towards(lights, far.position, 0.5f);
    const uint64_t atA = slotsAt(*ctx, scene, a, lights), atFar = slotsAt(*ctx, scene, far, lights),
                   closeAtFar = slotsAt(*ctx, scene, far, close);
    // The views this test needs: one within A's room, one past it.
    ASSERT_LE(atFar, atA);
    ASSERT_GT(closeAtFar, atA);

    RenderSettings settings;
    settings.width = kW;
    settings.height = kH;
    settings.knobs = GetParam();
    Result<const RendererEntry*> entry = findRenderer("forwardplus");
    ASSERT_TRUE(entry.ok());
    scene.camera = a;
    SceneGpu gpu(*ctx, scene);
    auto session = RendererSession::create(*ctx, gpu, **entry, analyzeScene(scene, 1), settings);
    ASSERT_TRUE(session.ok()) << session.error();
    const RunResult first = render(**session);
    const double lists = first.stats.counter("light_lists"); // 2 with blended surfaces
    EXPECT_EQ(first.stats.counter("light_list_slots"), double(atA) * lists); // A's need, exactly

    scene.camera = far;
    const RunResult atFarInPlace = render(**session);
    EXPECT_EQ((*session)->updates(), 1u);
    EXPECT_EQ((*session)->replans(), 0u) << "a view within the room is followed in place";
    expectPlannedThere(*ctx, scene, **entry, settings, atFarInPlace, "in place");
    // --light-bin gpu, tiled: the view followed with no sizing run (no readback): the frame
    // laid it out (core/passes/light_binning.h).
    const bool gpuTiled = GetParam().count("light-bin") && GetParam().at("light-bin") == "gpu" &&
                          !GetParam().count("light-assign");
    if (gpuTiled) {
        EXPECT_EQ(atFarInPlace.stats.counter("light_bin_sizing_runs"), 1.0);
    }

    gpu.setLights(close); // the lights come close to the eye: more tiles each
    scene.lights = close;
    const RunResult moved = render(**session);
    EXPECT_EQ((*session)->replans(), 1u) << "a view past the room is planned again, counted";
    EXPECT_EQ(moved.stats.counter("view_replans"), 1.0);
    EXPECT_EQ(moved.stats.counter("light_list_slots"), double(closeAtFar) * lists);
    EXPECT_EQ(moved.stats.counter("lights_dropped", -1.0), 0.0);
    // GPU binning: the overflow was counted by the frame, then planned again (one sizing run).
    if (gpuTiled) {
        EXPECT_EQ(moved.stats.counter("light_bin_sizing_runs"), 1.0);
    }

    expectPlannedThere(*ctx, scene, **entry, settings, moved, "planned again");
    expectNoValidationMessages(*ctx);
}

INSTANTIATE_TEST_SUITE_P(
    Binning, ForwardPlusViews,
    ::testing::Values(std::map<std::string, std::string>{{"light-bin", "cpu"}},
                      std::map<std::string, std::string>{{"light-bin", "gpu"}},
                      std::map<std::string, std::string>{{"light-assign", "clustered"},
                                                         {"light-bin", "cpu"}}),
    [](const auto& info) {
        std::string n;
        for (const auto& [k, v] : info.param)
            n += (n.empty() ? "" : "_") + v;
        return n;
    });

} // namespace
} // namespace tp::test
