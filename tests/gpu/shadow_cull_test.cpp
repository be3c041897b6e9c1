// --cull-geometry frustum on the shadow faces (core/passes/shadow_cull.h, docs/shadows.md,
// "Culling the faces' meshlets"): each face's meshlets culled by the face's frustum and the
// light's range before the map is drawn. courtyard-small, 64 lights of the generator's default
// ranges, 16 shadowed, validation with synchronization validation on.
//
// The maps: the atlas culled and unculled, texel by texel. The frustum drops only what has no
// fragment in the face; the range drops only meshlets wholly farther from the light than
// range (1 + TP_SC_RANGE_FOOTPRINTS footprints), so every texel whose unculled depth lies
// within range (1 + 3 footprints), where an occluder can still darken a lit receiver's tap, is
// the same bit for bit, and elsewhere the culled texel is never nearer.
// The images: every residency (the kept atlas, the atlas in every frame, one light's map at a
// time in deferred's volumes and multipass forward's light passes), 1x and 4x, the same bit for
// bit, depth too, with the counters adding up and both tests culling something.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/gpu/readback.h"
#include "core/passes/shadow_maps.h"
#include "core/runner/render_session.h"
#include "gpu_test_util.h"

namespace tp::test {
namespace {

constexpr uint32_t kShadowedLights = 16;

Scene shadowCourtyard() {
    return courtyardSmallWithLights(64, 3);
}

void expectShadowCountersAddUp(const std::vector<std::pair<std::string, double>>& counters,
                               const std::string& what) {
    auto get = [&](const std::string& name) {
        for (const auto& [n, v] : counters)
            if (n == name) return v;
        return -1.0;
    };
    const double meshlets = get("shadow_meshlets"), submitted = get("shadow_meshlets_submitted");
    const double frustum = get("shadow_meshlets_culled_frustum");
    const double range = get("shadow_meshlets_culled_range");
    const double triangles = get("shadow_triangles");
    const double trianglesSubmitted = get("shadow_triangles_submitted");
    std::printf("[ shadow cull ] %s: %.0f meshlets: %.0f submitted, %.0f culled by the faces' "
                "frustums, %.0f by the lights' ranges; %.0f of %.0f triangles submitted\n",
                what.c_str(), meshlets, submitted, frustum, range, trianglesSubmitted, triangles);
    EXPECT_GT(meshlets, 0) << what;
    EXPECT_EQ(submitted + frustum + range, meshlets) << what;
    EXPECT_GT(submitted, 0) << what;
    EXPECT_GT(frustum, 0) << what;
    EXPECT_GT(range, 0) << what;
    EXPECT_GT(trianglesSubmitted, 0) << what;
    EXPECT_LT(trianglesSubmitted, triangles) << what;
}

TEST(ShadowCull, AtlasTheSameWhereverTheLightReaches) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = shadowCourtyard();
    SceneGpu gpu(*ctx, scene);
    gpu.setView(96, 54, 1);
    ShadowSettings settings;
    settings.count = kShadowedLights;
    settings.cache = false;
    planSceneShadows(*ctx, gpu, settings);
    const ShadowPlan plan = gpu.shadowPlan();
    ASSERT_EQ(plan.lights.size(), kShadowedLights);

    const ShadowAtlasRun none = renderShadowAtlas(*ctx, gpu, CullGeometry::None);
    const ShadowAtlasRun culled = renderShadowAtlas(*ctx, gpu, CullGeometry::Frustum);
    expectNoValidationMessages(*ctx);
    ASSERT_EQ(none.depth.r.size(), culled.depth.r.size());
    expectShadowCountersAddUp(culled.counters, "atlas, 16 shadowed lights");

    // Per face: its texels' distances from the light (near / depth along the axis, times the
    // ray's length per unit of axis), against the reach within which an occluder can darken a
    // PCF tap of a lit receiver: range (1 + 3 footprints), derived in docs/shadows.md
    // independently of the margin the shader keeps (TP_SC_RANGE_FOOTPRINTS).
    size_t within = 0, withinDiffer = 0, nearer = 0, beyondDiffer = 0, covered = 0;
    for (const gpu::ShadowFace& f : plan.faces) {
        const float range = gpu.lightsGpu()[f.atlas.w].range;
        const double reach = range * (1.0 + 3.0 * f.params.x);
        const uint32_t edge = f.atlas.z;
        const double halfTan = f.params.x * edge / 2.0; // tan(fov / 2)
        for (uint32_t y = 0; y < edge; ++y)
            for (uint32_t x = 0; x < edge; ++x) {
                const size_t i = size_t(f.atlas.y + y) * none.depth.width + f.atlas.x + x;
                const float a = none.depth.r[i], b = culled.depth.r[i];
                if (a > 0.0f) ++covered;
                const double u = ((x + 0.5) / edge * 2.0 - 1.0) * halfTan;
                const double v = ((y + 0.5) / edge * 2.0 - 1.0) * halfTan;
                const double dist =
                    a > 0.0f ? f.params.y / a * std::sqrt(1.0 + u * u + v * v) : INFINITY;
                const bool differ = std::memcmp(&a, &b, sizeof(float)) != 0;
                nearer += b > a; // culling may only take fragments away
                if (dist <= reach) {
                    ++within;
                    withinDiffer += differ;
                } else {
                    beyondDiffer += differ;
                }
            }
    }
    std::printf("[ shadow cull ] atlas %ux%u, %zu faces: %zu texels covered, %zu within the "
                "lights' reach (%zu differ), %zu beyond differ, %zu nearer culled\n",
                none.depth.width, none.depth.height, plan.faces.size(), covered, within,
                withinDiffer, beyondDiffer, nearer);
    EXPECT_GT(within, 0u);
    EXPECT_EQ(withinDiffer, 0u) << "culling changed a texel the light reaches";
    EXPECT_EQ(nearer, 0u) << "a culled texel is nearer than the unculled one";
}

struct ShadowCullCase {
    std::string pipeline;
    std::vector<std::pair<std::string, std::string>> knobs;
    bool cache = true;
    uint32_t msaa = 1;
    std::string name() const {
        std::string n = pipeline;
        for (const auto& [k, v] : knobs)
            n += " --" + k + " " + v;
        return n + (cache ? "" : " --shadow-cache off") + " " + std::to_string(msaa) + "x";
    }
};

void expectSameShadowedImage(const ShadowCullCase& c) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = shadowCourtyard();
    SceneGpu gpu(*ctx, scene);
    RenderSettings s;
    s.width = 96;
    s.height = 54;
    s.msaa = c.msaa;
    s.shadows.count = kShadowedLights;
    s.shadows.cache = c.cache;
    for (const auto& [k, v] : c.knobs)
        s.set(k, v);
    const RunResult none = runOrFail(*ctx, gpu, c.pipeline, s);
    s.set("cull-geometry", "frustum");
    const RunResult culled = runOrFail(*ctx, gpu, c.pipeline, s, 2);
    expectNoValidationMessages(*ctx);
    const std::string what = c.name();
    EXPECT_EQ(none.stats.counter("shadow_meshlets_submitted", -1), -1) << "none counts nothing";
    EXPECT_EQ(none.stats.counter("shadow_triangles", -1),
              culled.stats.counter("shadow_triangles", -2))
        << what;
    expectShadowCountersAddUp(culled.stats.counters, what);
    ASSERT_EQ(none.depth.r, culled.depth.r) << what << ": culling changed the depth";
    const size_t differ = differingPixels(none.hdr, culled.hdr);
    std::printf("[ shadow cull ] %s: %zu of %zu pixels differ\n", what.c_str(), differ,
                none.hdr.pixelCount());
    EXPECT_EQ(differ, 0u) << what;
}

// The shadows must show in these images, or the test would hold whatever the maps held.
TEST(ShadowCull, ShadowsShowInTheImage) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = shadowCourtyard();
    SceneGpu gpu(*ctx, scene);
    RenderSettings s;
    s.width = 96;
    s.height = 54;
    const RunResult unshadowed = runOrFail(*ctx, gpu, "forwardplus", s);
    s.shadows.count = kShadowedLights;
    const RunResult shadowed = runOrFail(*ctx, gpu, "forwardplus", s);
    const size_t differ = differingPixels(unshadowed.hdr, shadowed.hdr);
    std::printf("[ shadow cull ] %zu of %zu pixels darkened by the shadows\n", differ,
                shadowed.hdr.pixelCount());
    EXPECT_GT(differ, 50u);
}

// The kept atlas (rendered once, outside the frames) and the atlas of every frame.
TEST(ShadowCull, ForwardPlusKeptAtlasSameImage) {
    expectSameShadowedImage({"forwardplus", {}, true, 1});
}
TEST(ShadowCull, ForwardPlusKeptAtlasSameImageMsaa4) {
    expectSameShadowedImage({"forwardplus", {}, true, 4});
}
TEST(ShadowCull, ForwardPlusAtlasEveryFrameSameImage) {
    expectSameShadowedImage({"forwardplus", {}, false, 1});
}
TEST(ShadowCull, VisbufferAtlasEveryFrameSameImageMsaa4) {
    expectSameShadowedImage({"visbuffer", {}, false, 4});
}
// One light's map at a time, inside the lighting passes.
TEST(ShadowCull, DeferredVolumesSameImage) {
    expectSameShadowedImage({"deferred", {{"deferred-lighting", "volumes"}}, true, 1});
}
TEST(ShadowCull, DeferredVolumesSameImageMsaa4) {
    expectSameShadowedImage({"deferred", {{"deferred-lighting", "volumes"}}, true, 4});
}
TEST(ShadowCull, MultipassForwardSameImage) {
    expectSameShadowedImage({"multipass_forward", {}, true, 1});
}

// Lights that move between the views of a planned renderer (RendererSession): the faces' rows
// follow (ShadowMaps::stale: uploaded again, the kept atlas rendered again, or a new plan when
// they outgrow what was planned), and the image is what an unculled renderer planned there
// renders, bit for bit.
void expectMovedLightsAsUnculled(const std::string& pipeline, bool cache) {
    SCOPED_TRACE(pipeline + (cache ? "" : " --shadow-cache off"));
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = shadowCourtyard();
    RenderSettings s;
    s.width = 96;
    s.height = 54;
    s.shadows.count = kShadowedLights;
    s.shadows.cache = cache;
    s.manyViews = true;
    std::vector<Light> moved = scene.lights;
    for (size_t i = 0; i < moved.size(); ++i)
        moved[i].position +=
            glm::vec3(0.02f * std::sin(float(i)), 0.01f, 0.02f * std::cos(float(i)));
    SceneGpu gpu(*ctx, scene);
    RenderSettings culled = s;
    culled.set("cull-geometry", "frustum");
    Result<const RendererEntry*> entry = findRenderer(pipeline);
    ASSERT_TRUE(entry.ok());
    auto session = RendererSession::create(*ctx, gpu, **entry, analyzeScene(scene, 1), culled);
    ASSERT_TRUE(session.ok()) << session.error();
    RunOptions once;
    once.warmupFrames = 0;
    once.timedFrames = 1;
    ASSERT_TRUE((*session)->render(once).ok());
    gpu.setLights(moved);
    Result<RunResult> after = (*session)->render(once);
    ASSERT_TRUE(after.ok()) << after.error();
    const RunResult fresh = runOrFail(*ctx, gpu, pipeline, s);
    expectNoValidationMessages(*ctx);
    std::printf("[ shadow cull ] %s, lights moved: %u updates, %u replans, %zu pixels differ\n",
                pipeline.c_str(), (*session)->updates(), (*session)->replans(),
                differingPixels(after->hdr, fresh.hdr));
    EXPECT_EQ((*session)->updates(), 1u) << "moved 2 cm: the same plan, followed in place";
    EXPECT_EQ(differingPixels(after->hdr, fresh.hdr), 0u);
    EXPECT_EQ(after->depth.r, fresh.depth.r);
}

TEST(ShadowCull, MovedLightsAsUnculled) {
    expectMovedLightsAsUnculled("forwardplus", true);
    expectMovedLightsAsUnculled("forwardplus", false);
    expectMovedLightsAsUnculled("multipass_forward", true);
}

} // namespace
} // namespace tp::test
