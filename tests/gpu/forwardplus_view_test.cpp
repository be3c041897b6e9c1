// Forward+ planned once, moved to other views (forwardplus/view_bins.h; the contract's step 6):
// a view whose lists fit the planned room is followed in place; a view that needs more slots
// than the plan holds is refused by updateView (CPU binning) or counted by the frame (GPU
// binning: Renderer::overflowed, rendered again) and planned again, counted (view_replans) -
// never silent, never a cut list - and renders what a renderer planned there renders.
// view_update_test.cpp checks the ordinary views of every configuration with headroom; here
// the lists are sized exactly (RenderSettings::manyViews off), so the room is the first view's.
#include <cstdio>
#include <cstring>
#include <map>
#include <string>

#include "core/lightassign/light_bins.h"
#include "core/lightassign/light_classes.h"
#include "core/lightassign/tile_grid.h"
#include "core/runner/frame_runner.h"
#include "core/runner/render_session.h"
#include "forwardplus/light_lists.h"
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

// --light-bin cpu and gpu (the frame lays the view out and counts an overflow, read after the
// view's frames), tiled and clustered (the mask rows' room too).
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
    // Binned: --light-cull auto is `all` on a GPU up to 2,048 lights (no runs to follow).
    settings.knobs["light-cull"] = "binned";
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
    // --light-bin gpu, tiled or clustered: the view followed with no sizing run (no readback):
    // the frame laid it out (core/passes/light_binning.h).
    const bool gpuBinned = GetParam().count("light-bin") && GetParam().at("light-bin") == "gpu";
    if (gpuBinned) {
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
    if (gpuBinned) {
        EXPECT_EQ(moved.stats.counter("light_bin_sizing_runs"), 1.0);
    }

    expectPlannedThere(*ctx, scene, **entry, settings, moved, "planned again");
    expectNoValidationMessages(*ctx);
}

INSTANTIATE_TEST_SUITE_P(Binning, ForwardPlusViews,
                         ::testing::Values(std::map<std::string, std::string>{{"light-bin", "cpu"}},
                                           std::map<std::string, std::string>{{"light-bin", "gpu"}},
                                           std::map<std::string, std::string>{
                                               {"light-assign", "clustered"}, {"light-bin", "cpu"}},
                                           std::map<std::string, std::string>{
                                               {"light-assign", "clustered"},
                                               {"light-bin", "gpu"}}),
                         [](const auto& info) {
                             std::string n;
                             for (const auto& [k, v] : info.param)
                                 n += (n.empty() ? "" : "_") + v;
                             return n;
                         });

// ---- clustered, --light-bin gpu: the mask rows outgrow their room while the runs fit ----

// Where the ray through pixel (x, y) (row 0 at the top) meets the plane y = height.
glm::vec3 onFloor(const Camera& cam, float x, float y, float height) {
    const glm::vec3 f = glm::normalize(cam.target - cam.position);
    const glm::vec3 r = glm::normalize(glm::cross(f, cam.up)), u = glm::cross(r, f);
    const float t = std::tan(cam.yfov * 0.5f);
    const glm::vec3 dir = f + r * ((2.0f * x / kW - 1.0f) * t * float(kW) / float(kH)) +
                          u * ((1.0f - 2.0f * y / kH) * t);
    return cam.position + dir * ((height - cam.position.y) / dir.y);
}

// 64 small point lights just above the floor: all at one point where four tiles meet
// (`packed`: 4 tiles of 64 candidates, two words a slice row), or one per tile centre of the
// tiles that see the floor (spread: fewer candidates in all, but one word a row in each of
// many more tiles).
std::vector<Light> floorLights(const Camera& cam, bool packed) {
    std::vector<glm::vec3> at;
    if (packed) at.push_back(onFloor(cam, 48.0f, 48.0f, 0.05f));
    for (uint32_t ty = 0; !packed && ty < kH / 16; ++ty)
        for (uint32_t tx = 0; tx < kW / 16; ++tx) {
            const glm::vec3 p = onFloor(cam, 16.0f * tx + 8.0f, 16.0f * ty + 8.0f, 0.05f);
            const bool inFront = glm::dot(p - cam.position, cam.target - cam.position) > 0.0f;
            if (inFront && std::abs(p.x) < 4.5f && std::abs(p.z) < 4.5f) at.push_back(p);
        }
    std::vector<Light> lights(64);
    for (size_t i = 0; i < lights.size(); ++i) {
        lights[i].position = at[i % at.size()];
        lights[i].range = 0.3f;
        lights[i].intensity = 2.0f;
        lights[i].color =
            glm::vec3(0.2f + 0.8f * float(i % 3 == 0), 0.2f + 0.8f * float(i % 3 == 1),
                      0.2f + 0.8f * float(i % 3 == 2));
    }
    return lights;
}

struct ClusterNeed {
    uint64_t slots = 0, words = 0;
    uint32_t longest = 0;
};

// What the CPU lays out for the scene's view with these lights: slots, mask words, longest run.
ClusterNeed clusterNeed(GpuContext& ctx, Scene scene, const std::vector<Light>& lights,
                        uint32_t slices) {
    scene.lights = lights;
    SceneGpu gpu(ctx, scene);
    gpu.setView(kW, kH, 1);
    const gpu::FrameUniforms& f = gpu.shadingFrame();
    const std::vector<uint32_t> local = la::classifyLights(gpu.shadingLights()).local;
    const la::LightBins bins = la::binLights(la::makeTileGrid(kW, kH, 16), f.view, f.proj,
                                             gpu.shadingLights(), local, false);
    return {bins.slots, fp::layoutMasks(bins.bound, slices).words, bins.maxBound};
}

// Planned exactly for the packed lights, the spread ones need more mask words than the plan
// holds though their runs fit: the frame clamps the rows (the culling keeps what they hold
// and counts the rest dropped: nothing written past them), overflowed() counts it, and the
// session plans again and renders what a renderer planned there renders.
TEST(ForwardPlusClusteredViews, MaskRowsPastTheRoomArePlannedAgain) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = makeFloorScene({});
    const std::vector<Light> packed = floorLights(scene.camera, true),
                             spread = floorLights(scene.camera, false);
    const uint32_t slices = 16;
    const ClusterNeed a = clusterNeed(*ctx, scene, packed, slices),
                      b = clusterNeed(*ctx, scene, spread, slices);
    std::printf("[ clustered view ] packed: %llu slots, %llu mask words, longest run %u; spread: "
                "%llu, %llu, %u\n",
                (unsigned long long)a.slots, (unsigned long long)a.words, a.longest,
                (unsigned long long)b.slots, (unsigned long long)b.words, b.longest);
    ASSERT_LE(b.slots, a.slots) << "the runs fit the room";
    ASSERT_LE(b.longest, a.longest);
    ASSERT_GT(b.words, a.words) << "the mask rows do not";

    RenderSettings settings;
    settings.width = kW;
    settings.height = kH;
    settings.knobs = {{"light-assign", "clustered"}, {"light-bin", "gpu"}, {"slices", "16"},
                      {"light-cull", "binned"}}; // auto is `all` on a GPU at this count
    const RendererEntry& entry = **findRenderer("forwardplus");
    scene.lights = packed;

    // The frame past the room, run by hand: cut at the rows, counted.
    {
        SceneGpu gpu(*ctx, scene);
        gpu.setView(kW, kH, 1);
        Result<PlannedRenderer> p =
            planRenderer(*ctx, gpu, entry, analyzeScene(scene, 1), settings);
        ASSERT_TRUE(p.ok()) << p.error();
        p->renderer->prepare(*p->graph);
        recordAndSubmit(*ctx, *p->graph);
        EXPECT_FALSE(p->renderer->overflowed(*p->graph));
        gpu.setLights(spread);
        gpu.setView(kW, kH, 1);
        ASSERT_TRUE(p->renderer->updateView(*p->graph)) << "nothing read back: followed in place";
        recordAndSubmit(*ctx, *p->graph);
        EXPECT_TRUE(p->renderer->overflowed(*p->graph));
        p->renderer->collectStats(*p->graph);
        EXPECT_GT(p->renderer->stats().counter("lights_dropped"), 0.0)
            << "the rows past the room hold no lights: the culling kept none there";
    }

    SceneGpu gpu(*ctx, scene);
    auto session = RendererSession::create(*ctx, gpu, entry, analyzeScene(scene, 1), settings);
    ASSERT_TRUE(session.ok()) << session.error();
    const RunResult first = render(**session);
    EXPECT_EQ(first.stats.counter("cluster_mask_words"), double(a.words)); // exactly A's
    gpu.setLights(spread);
    scene.lights = spread;
    const RunResult moved = render(**session);
    EXPECT_EQ((*session)->updates(), 1u) << "followed in place first";
    EXPECT_EQ((*session)->replans(), 1u) << "the overflow counted and planned again";
    EXPECT_EQ(moved.stats.counter("view_replans"), 1.0);
    EXPECT_EQ(moved.stats.counter("light_bin_sizing_runs"), 1.0) << "one, at the replan";
    EXPECT_EQ(moved.stats.counter("cluster_mask_words"), double(b.words));
    EXPECT_EQ(moved.stats.counter("lights_dropped", -1.0), 0.0);
    EXPECT_GT(moved.stats.counter("lights_kept"), 0.0) << "the lights reach the floor";
    expectPlannedThere(*ctx, scene, entry, settings, moved, "planned again");
    // And a fresh plan there is CPU binning's image, bit for bit (the GPU's rows are the CPU's).
    RenderSettings cpu = settings;
    cpu.knobs["light-bin"] = "cpu";
    expectPlannedThere(*ctx, scene, entry, cpu, moved, "against CPU binning");
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
