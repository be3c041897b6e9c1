// --cull-geometry frustum (core/passes/meshlet_cull.h, docs/geometry.md) on every pipeline
// that reads it (the registry's list: Forward+, deferred, the visibility buffer, multipass
// forward): the culled frame against the unculled one (depth bit for bit, colour the same: a
// depth tie between coplanar triangles of one mesh could resolve in another order, and none of
// these scenes has one), the counters adding up, and mirrored node transforms (negative
// scales) cone-culled correctly. The visibility buffer's ids of culled meshlets must be the
// ones whole draws write, or its resolve would shade other triangles. Validation with
// synchronization validation on.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/reference/reference_renderer.h"
#include "core/scene/gltf_loader.h"
#include "gpu_test_util.h"
#include "temp_path.h"
#include "transformed_scenes.h"

namespace tp::test {
namespace {

struct Pair {
    RunResult none, frustum;
};

// `pipeline` unculled and with --cull-geometry frustum (its second frame too).
Pair renderBoth(const std::string& pipeline, const Scene& scene, uint32_t w, uint32_t h,
                uint32_t msaa) {
    std::vector<RunResult> v = renderCullModes(pipeline, scene, w, h, msaa, "frustum", {2});
    if (v.size() < 2) return {};
    return {std::move(v[0]), std::move(v[1])};
}

void expectSameFrame(const Pair& p, const std::string& what) {
    ASSERT_EQ(p.none.depth.r.size(), p.frustum.depth.r.size());
    EXPECT_EQ(p.none.depth.r, p.frustum.depth.r) << what << ": culling changed the depth";
    const uint64_t differ = differingPixels(p.none.hdr, p.frustum.hdr);
    std::printf("[ meshlet cull ] %s: %llu of %zu pixels differ in colour\n", what.c_str(),
                (unsigned long long)differ, p.none.hdr.pixelCount());
    EXPECT_EQ(differ, 0u) << what;
}

void expectCountersAddUp(const RunResult& r, const std::string& what) {
    const double meshlets = r.stats.counter("meshlets", -1);
    const double submitted = r.stats.counter("meshlets_submitted", -1);
    const double frustum = r.stats.counter("meshlets_culled_frustum", -1);
    const double cone = r.stats.counter("meshlets_culled_cone", -1);
    const double triangles = r.stats.counter("triangles", -1);
    const double trianglesSubmitted = r.stats.counter("triangles_submitted", -1);
    std::printf("[ meshlet cull ] %s: %.0f meshlets: %.0f submitted, %.0f culled by the frustum, "
                "%.0f by the cone; %.0f of %.0f triangles submitted\n",
                what.c_str(), meshlets, submitted, frustum, cone, trianglesSubmitted, triangles);
    EXPECT_GT(meshlets, 0) << what;
    EXPECT_EQ(submitted + frustum + cone, meshlets) << what;
    EXPECT_GT(submitted, 0) << what;
    EXPECT_GT(trianglesSubmitted, 0) << what;
    EXPECT_LE(trianglesSubmitted, triangles) << what;
}

class CulledFrame : public ::testing::TestWithParam<std::string> {};

TEST_P(CulledFrame, CourtyardSmallSameFrameAndCounters) {
    Scene scene = courtyardSmallWithLights(64, 3);
    const std::string what = GetParam() + ", courtyard-small 1x";
    Pair p = renderBoth(GetParam(), scene, 96, 54, 1);
    expectSameFrame(p, what);
    expectCountersAddUp(p.frustum, what);
    // The default view sees part of the courtyard, and half of what it sees faces away.
    EXPECT_GT(p.frustum.stats.counter("meshlets_culled_frustum"), 0);
    EXPECT_GT(p.frustum.stats.counter("meshlets_culled_cone"), 0);
    EXPECT_EQ(p.none.stats.counter("meshlets_submitted", -1), -1) << "none counts nothing";
}

TEST_P(CulledFrame, CourtyardSmallSameFrameMsaa4) {
    Scene scene = courtyardSmallWithLights(64, 3);
    const std::string what = GetParam() + ", courtyard-small 4x";
    Pair p = renderBoth(GetParam(), scene, 96, 54, 4);
    expectSameFrame(p, what);
    expectCountersAddUp(p.frustum, what);
}

// Views from inside the colonnade and from below the ground: more of the scene culled.
TEST_P(CulledFrame, CourtyardSmallOtherViews) {
    Scene scene = courtyardSmallWithLights(16, 5);
    const glm::vec3 c = scene.bounds.center(), e = scene.bounds.extent();
    const glm::vec3 eyes[] = {c + e * glm::vec3(0.42f, -0.3f, 0.05f),
                              c + e * glm::vec3(-0.1f, -0.45f, 0.3f)};
    for (const glm::vec3& eye : eyes) {
        scene.camera.position = eye;
        scene.camera.target = c;
        const std::string what = GetParam() + ", courtyard-small, another view";
        Pair p = renderBoth(GetParam(), scene, 64, 48, 1);
        expectSameFrame(p, what);
        expectCountersAddUp(p.frustum, what);
    }
}

// Negative and non-uniform node scales (every mesh single-sided): the loader flips a mirrored
// node's winding, so the cones built from world-space triangles follow the front faces.
TEST_P(CulledFrame, MirroredNodesSameFrame) {
    for (uint32_t seed : {2u, 5u}) {
        const auto dir = testTempPath("meshlet_cull_" + std::to_string(seed));
        Result<Scene> s = loadGltf(writeTransformedNodesScene(dir, seed).string());
        ASSERT_TRUE(s.ok()) << s.error();
        Scene scene = std::move(*s);
        scene.lights = lightsGrazingSurfaces(scene, 16, seed);
        const std::string what = GetParam() + ", mirrored nodes, seed " + std::to_string(seed);
        Pair p = renderBoth(GetParam(), scene, 96, 72, 1);
        expectSameFrame(p, what);
        expectCountersAddUp(p.frustum, what);
    }
}

INSTANTIATE_TEST_SUITE_P(MeshletCull, CulledFrame, ::testing::ValuesIn(cullingPipelines()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return info.param;
                         });

// Every pipeline culls its geometry passes; the reference stays brute force (its image is
// the ground truth the others' errors are measured against).
TEST(MeshletCullKnob, ReadByEveryPipelineButTheReference) {
    const std::vector<std::string> culling = cullingPipelines();
    for (const RendererEntry& e : registeredRenderers())
        EXPECT_EQ(std::count(culling.begin(), culling.end(), e.name) == 1,
                  e.name != kReferenceRenderer)
            << e.name;
}

} // namespace
} // namespace tp::test
