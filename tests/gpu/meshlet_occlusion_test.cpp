// --cull-geometry full (core/passes/meshlet_cull.h, core/passes/depth_pyramid.h,
// docs/geometry.md "Occlusion") on every pipeline that reads the knob (the registry's list):
// the image of every frame, the first (every meshlet treated as visible) and later ones (the
// history of the frame before), is the unculled one, depth bit for bit and no pixel of another
// colour; the counters add up over the two phases; a wall in front of many objects hides most
// of their meshlets; the view from inside the colonnade (docs/recipes/courtyard_colonnade_
// camera.json, the benchmark's) is the same image too. A moved camera (a history from another
// view) is tests/gpu/view_update_test.cpp's. Validation with synchronization validation on.
#include <algorithm>
#include <cmath>

#include "core/camera/camera_file.h"
#include "core/runner/render_session.h"
#include "core/scene/lights.h"
#include "core/scene/mesh_builder.h"
#include "core/scene/procedural.h"
#include "gpu_test_util.h"

namespace tp::test {
namespace {

struct Runs {
    RunResult none, first, later; // later: the last of `frames` frames
};

// `pipeline` unculled (one frame) and with --cull-geometry full, one frame and `frames`.
Runs renderRuns(const std::string& pipeline, const Scene& scene, uint32_t w, uint32_t h,
                uint32_t msaa, uint32_t frames = 3) {
    std::vector<RunResult> v = renderCullModes(pipeline, scene, w, h, msaa, "full", {1, frames});
    if (v.size() < 3) return {};
    return {std::move(v[0]), std::move(v[1]), std::move(v[2])};
}


void expectSameFrame(const RunResult& none, const RunResult& full, const std::string& what) {
    ASSERT_EQ(none.depth.r.size(), full.depth.r.size()) << what;
    ASSERT_FALSE(none.depth.r.empty()) << what;
    EXPECT_EQ(none.depth.r, full.depth.r) << what << ": occlusion culling changed the depth";
    const uint64_t differ = differingPixels(none.hdr, full.hdr);
    std::printf("[ occlusion ] %s: %llu of %zu pixels differ in colour\n", what.c_str(),
                (unsigned long long)differ, none.hdr.pixelCount());
    EXPECT_EQ(differ, 0u) << what;
}

struct Counts {
    double meshlets, submitted, frustum, cone, occlusion, early, late;
};

Counts countersOf(const RunResult& r, const std::string& what) {
    auto c = [&](const char* name) { return r.stats.counter(name, -1); };
    Counts n{c("meshlets"),
             c("meshlets_submitted"),
             c("meshlets_culled_frustum"),
             c("meshlets_culled_cone"),
             c("meshlets_culled_occlusion"),
             c("meshlets_submitted_early"),
             c("meshlets_submitted_late")};
    std::printf("[ occlusion ] %s: %.0f meshlets: %.0f submitted (%.0f early, %.0f late), culled "
                "%.0f by the frustum, %.0f by the cone, %.0f by occlusion; %.0f + %.0f of %.0f "
                "triangles\n",
                what.c_str(), n.meshlets, n.submitted, n.early, n.late, n.frustum, n.cone,
                n.occlusion, c("triangles_submitted_early"), c("triangles_submitted_late"),
                c("triangles"));
    EXPECT_GT(n.meshlets, 0) << what;
    EXPECT_GE(n.occlusion, 0) << what << ": no occlusion counter";
    EXPECT_EQ(n.submitted + n.frustum + n.cone + n.occlusion, n.meshlets) << what;
    EXPECT_EQ(n.early + n.late, n.submitted) << what;
    EXPECT_EQ(c("triangles_submitted_early") + c("triangles_submitted_late"),
              c("triangles_submitted"))
        << what;
    return n;
}

// Every frame the same image as unculled; the second frame on draws last frame's visible set
// early, and a view that does not move leaves the late phase nothing to add.
void expectSameOverFrames(const Runs& r, const std::string& what) {
    expectSameFrame(r.none, r.first, what + ", frame 1");
    expectSameFrame(r.none, r.later, what + ", frame 3");
    const Counts first = countersOf(r.first, what + ", frame 1");
    const Counts later = countersOf(r.later, what + ", frame 3");
    // The first frame treats every meshlet as visible: all drawn early, none culled by
    // occlusion (its late phase only finds the hidden ones for the next frame).
    EXPECT_EQ(first.late, 0) << what;
    EXPECT_EQ(first.occlusion, 0) << what;
    EXPECT_GT(later.early, 0) << what;
    EXPECT_EQ(later.late, 0) << what << ": a still view's history is its visible set";
    // Multipass forward counts its prepass draws (placed against draw_culled): the late phase
    // records every draw of the prepass again (as its late meshlets); unculled, it has none.
    const double late = r.first.stats.counter("depth_prepass_late_draws", -1);
    if (late >= 0) {
        EXPECT_GT(late, 0) << what;
        EXPECT_EQ(late, r.first.stats.counter("depth_prepass_draws")) << what;
        EXPECT_EQ(r.none.stats.counter("depth_prepass_late_draws"), 0) << what;
    }
}

class OccludedFrame : public ::testing::TestWithParam<std::string> {};

TEST_P(OccludedFrame, CourtyardSmallSameFrameOverFrames) {
    Scene scene = courtyardSmallWithLights(32, 3);
    for (uint32_t msaa : {1u, 4u}) {
        const std::string what =
            GetParam() + ", courtyard-small " + std::to_string(msaa) + "x";
        expectSameOverFrames(renderRuns(GetParam(), scene, 96, 54, msaa), what);
    }
}

// The benchmark's view from inside the colonnade (docs/geometry.md) of the full courtyard (its
// small meshlets; courtyard-small's cover too much of a test-sized frame to be hidden): the
// columns and the back wall hide part of the courtyard.
TEST_P(OccludedFrame, ColonnadeViewSameFrame) {
    Result<Scene> courtyard = makeBuiltinScene("courtyard");
    ASSERT_TRUE(courtyard.ok()) << courtyard.error();
    Scene scene = std::move(*courtyard);
    LightGenOptions lights;
    lights.count = 16;
    lights.seed = 5;
    scene.lights = generateLights(scene.bounds, lights);
    Result<Camera> cam =
        readCameraFile(std::string(TP_SOURCE_DIR) + "/docs/recipes/courtyard_colonnade_camera.json");
    ASSERT_TRUE(cam.ok()) << cam.error();
    scene.camera = *cam;
    const std::string what = GetParam() + ", courtyard-small from the colonnade";
    const Runs r = renderRuns(GetParam(), scene, 128, 72, 1);
    expectSameOverFrames(r, what);
    EXPECT_GT(r.later.stats.counter("meshlets_culled_occlusion"), 0) << what;
}

// A stale history: a renderer that rendered the colonnade view, moved to the courtyard's own
// camera, finds most of what it now sees outside the last view's visible set (the colonnade's
// frustum culled 1,031 meshlets, the default view's 582): its late phase draws them, and the
// frame is the unculled one.
TEST_P(OccludedFrame, AMovedViewDrawsWhatItUncoversLate) {
    Result<Scene> courtyard = makeBuiltinScene("courtyard");
    ASSERT_TRUE(courtyard.ok()) << courtyard.error();
    Scene scene = std::move(*courtyard);
    LightGenOptions lights;
    lights.count = 16;
    lights.seed = 9;
    scene.lights = generateLights(scene.bounds, lights);
    const Camera home = scene.camera;
    Result<Camera> colonnade =
        readCameraFile(std::string(TP_SOURCE_DIR) + "/docs/recipes/courtyard_colonnade_camera.json");
    ASSERT_TRUE(colonnade.ok()) << colonnade.error();
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    SceneGpu gpu(*ctx, scene);
    RenderSettings s;
    s.width = 128;
    s.height = 72;
    s.manyViews = true;
    holdRasterFixed(s, GetParam());
    const RunResult none = runOrFail(*ctx, gpu, GetParam(), s);
    s.set("cull-geometry", "full");
    Result<const RendererEntry*> entry = findRenderer(GetParam());
    ASSERT_TRUE(entry.ok());
    auto session =
        RendererSession::create(*ctx, gpu, **entry, analyzeScene(scene, 1), s);
    ASSERT_TRUE(session.ok()) << session.error();
    RunOptions once;
    once.warmupFrames = 0;
    once.timedFrames = 1;
    scene.camera = *colonnade;
    ASSERT_TRUE((*session)->render(once).ok());
    scene.camera = home;
    Result<RunResult> moved = (*session)->render(once);
    ASSERT_TRUE(moved.ok()) << moved.error();
    const std::string what = GetParam() + ", courtyard, colonnade then its own camera";
    expectSameFrame(none, *moved, what);
    const Counts n = countersOf(*moved, what);
    EXPECT_GT(n.late, 100) << what << ": the late phase draws what the move uncovered";
    expectNoValidationMessages(*ctx);
}

INSTANTIATE_TEST_SUITE_P(MeshletOcclusion, OccludedFrame, ::testing::ValuesIn(cullingPipelines()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return info.param;
                         });

// A wall filling the view, a grid of spheres behind it (in the frustum, every one hidden) and a
// few in front of it.
Scene wallScene() {
    Scene s;
    s.source = "test:wall";
    Material grey;
    grey.name = "grey";
    grey.baseColorFactor = glm::vec4(0.7f, 0.7f, 0.7f, 1.0f);
    grey.metallicFactor = 0.0f;
    grey.roughnessFactor = 0.8f;
    Material red = grey;
    red.name = "red";
    red.baseColorFactor = glm::vec4(0.8f, 0.2f, 0.1f, 1.0f);
    s.materials = {grey, red};
    procgen::MeshBuilder wall("wall", 0);
    procgen::addBox(wall, {-12.0f, -8.0f, -0.5f}, {12.0f, 8.0f, 0.0f}, 1.0f);
    s.meshes.push_back(wall.finish());
    auto sphere = [](procgen::MeshBuilder& b, glm::vec3 c, float r) {
        procgen::addSurface(
            b, 16, 8,
            [c, r](float u, float v) {
                const float phi = 6.2831853f * u, theta = 3.1415927f * v;
                return c + r * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                         -std::sin(theta) * std::sin(phi));
            },
            [](float u, float v) { return glm::vec2(u, v); });
    };
    for (int row = 0; row < 6; ++row) { // behind: a mesh per row
        procgen::MeshBuilder b("hidden_" + std::to_string(row), 1);
        for (int i = 0; i < 10; ++i)
            sphere(b, {-6.3f + 1.4f * i, -3.5f + 1.4f * row, -3.0f - 1.5f * (i % 3)}, 0.6f);
        s.meshes.push_back(b.finish());
    }
    procgen::MeshBuilder front("in_front", 1);
    for (int i = 0; i < 3; ++i)
        sphere(front, {-3.0f + 3.0f * i, 0.0f, 2.0f}, 0.7f);
    s.meshes.push_back(front.finish());
    s.camera.position = {0.0f, 0.0f, 9.0f};
    s.camera.target = {0.0f, 0.0f, 0.0f};
    s.camera.yfov = 0.9f;
    s.camera.znear = 0.1f;
    s.ambient = glm::vec3(0.05f);
    s.computeBounds();
    LightGenOptions o;
    o.count = 8;
    o.seed = 11;
    s.lights = generateLights(s.bounds, o);
    return s;
}

// The counters must show occlusion culling most of the scene's meshlets: those of the hidden
// spheres that face the eye (all of them are in the view).
TEST(MeshletOcclusion, WallHidesTheMeshletsBehindIt) {
    const Scene scene = wallScene();
    for (const std::string& pipeline : {std::string("forwardplus"), std::string("visbuffer")}) {
        const std::string what = pipeline + ", wall scene";
        const Runs r = renderRuns(pipeline, scene, 96, 64, 1, 2);
        expectSameOverFrames(r, what);
        const Counts n = countersOf(r.later, what);
        EXPECT_GT(n.occlusion, 0.5 * n.meshlets) << what << ": most meshlets are behind the wall";
    }
}

} // namespace
} // namespace tp::test
