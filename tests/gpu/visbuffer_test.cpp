// The visibility buffer (docs/visbuffer.md) against the reference on the built-in courtyard,
// within the bound its error model derives (visbuffer/error_model.cpp), with validation on:
// 1x tiled and clustered, 4x with every sample shaded against the supersampled reference, 4x
// at the pixel rate against the centre reference (a pixel shaded once per triangle at its
// centre is what that reference computes per sample); edges exactly where the ids differ;
// the ledger's 8 bytes per sample. Blended surfaces both ways (--vis-blended compute, the
// default, and forward), over several lighting batches, and a pool too small for them
// counted, not silent; the many-views bound of the pool clipped at the near plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <vector>

#include "core/image/metrics.h"
#include "core/image/tonemap.h"
#include "core/renderer/error_model.h"
#include "core/renderer/renderer.h"
#include "core/runner/frame_runner.h"
#include "core/runner/render_session.h"
#include "core/scene/lights.h"
#include "gpu_test_util.h"
#include "visbuffer/draw_table.h"
#include "visbuffer/fragment_bound.h"
#include "visbuffer/lod_allowance.h"

namespace tp::test {
namespace {

RenderSettings small(uint32_t msaa, const std::string& shading = "pixel") {
    RenderSettings s;
    s.width = 96;
    s.height = 64;
    s.msaa = msaa;
    s.set("msaa-shading", shading);
    return s;
}

void expectWithinBound(GpuContext& ctx, const Scene& scene, const RunResult& run,
                       const RunResult& ref, const RenderSettings& modelSettings,
                       const std::string& what) {
    expectVisbufferWithinBound(ctx, scene, run, ref, modelSettings, what);
}

// Runs the visbuffer with `s` and checks it against `ref` with the model of the same settings.
void expectRunWithinBound(GpuContext& ctx, SceneGpu& gpuScene, const Scene& scene,
                          const RunResult& ref, const RenderSettings& s, const std::string& what) {
    expectWithinBound(ctx, scene, runOrFail(ctx, gpuScene, "visbuffer", s), ref, s, what);
}

TEST(Visbuffer, MatchesTheReferenceOnTheCourtyardWithinItsBound) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    for (uint32_t lights : {0u, 1u, 256u}) {
        Scene scene = courtyardSmallWithLights(lights, 3);
        SceneGpu gpuScene(*ctx, scene);
        const std::string n = std::to_string(lights) + " lights";
        RunResult ref = runOrFail(*ctx, gpuScene, "reference", small(1));
        expectRunWithinBound(*ctx, gpuScene, scene, ref, small(1), n + " 1x tiled");
        RenderSettings clustered = small(1);
        clustered.set("light-assign", "clustered");
        expectRunWithinBound(*ctx, gpuScene, scene, ref, clustered, n + " 1x clustered");
        RunResult ref4 = runOrFail(*ctx, gpuScene, "reference", small(4, "sample"));
        expectRunWithinBound(*ctx, gpuScene, scene, ref4, small(4, "sample"),
                             n + " 4x sample rate");
    }
    expectNoValidationMessages(*ctx);
}

// Untextured, the texture allowance is zero and the bound is the position allowance's and the
// scalar terms' alone: the floor scene (a box on a floor) at 1x and 4x.
TEST(Visbuffer, MatchesTheReferenceOnAnUntexturedFloorWithinItsBound) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    for (uint32_t count : {1u, 64u}) {
        LightGenOptions g;
        g.count = count;
        g.seed = 9;
        Scene probe = makeFloorScene({});
        Scene scene = makeFloorScene(generateLights(probe.bounds, g));
        SceneGpu gpuScene(*ctx, scene);
        const std::string n = std::to_string(count) + " lights floor";
        RunResult ref = runOrFail(*ctx, gpuScene, "reference", small(1));
        ASSERT_EQ(vis::textureLodAllowance(scene, ref.depth).r,
                  std::vector<float>(ref.depth.r.size(), 0.0f));
        expectRunWithinBound(*ctx, gpuScene, scene, ref, small(1), n + " 1x");
        RunResult ref4 = runOrFail(*ctx, gpuScene, "reference", small(4, "sample"));
        expectRunWithinBound(*ctx, gpuScene, scene, ref4, small(4, "sample"),
                             n + " 4x sample rate");
    }
    expectNoValidationMessages(*ctx);
}

// At the pixel rate a pixel is shaded once per distinct triangle at its centre, every sample
// of that triangle taking the value: the centre reference's per-sample computation. So the
// bound is the sample rate's (no centre-shading term), against that reference.
TEST(Visbuffer, PixelRateShadesEachTriangleOnceAtTheCentre) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    for (uint32_t lights : {1u, 256u}) {
        Scene scene = courtyardSmallWithLights(lights, 4);
        SceneGpu gpuScene(*ctx, scene);
        RenderSettings s = small(4, "pixel");
        s.debug = true;
        RunResult vis = runOrFail(*ctx, gpuScene, "visbuffer", s);
        RenderSettings centre = small(4, "pixel");
        centre.set("reference-msaa", "center");
        RunResult ref = runOrFail(*ctx, gpuScene, "reference", centre);
        expectWithinBound(*ctx, scene, vis, ref, small(4, "sample"),
                          std::to_string(lights) + " lights 4x pixel rate");
        // Edges: where the ids differ, counted by the pass and shown by --debug alike.
        const ImageRGBA* edges = debugImageOf(vis, "edge_mask");
        ASSERT_NE(edges, nullptr);
        size_t count = 0;
        for (size_t i = 0; i < edges->pixelCount(); ++i)
            count += edges->rgba[i * 4] > 0.5f ? 1 : 0;
        double share = -1;
        for (const auto& [name, value] : vis.stats.counters)
            if (name == "edge_pixel_share") share = value;
        EXPECT_GT(count, 0u) << "silhouettes hold several triangles per pixel";
        EXPECT_LT(count, edges->pixelCount() / 2) << "most pixels hold one triangle";
        EXPECT_DOUBLE_EQ(share, double(count) / double(edges->pixelCount()));
    }
    expectNoValidationMessages(*ctx);
}

// Blended surfaces composited in compute and drawn by the hybrid forward pass: each within the
// bound at 1x, 4x sample rate (supersampled reference) and 4x pixel rate (centre reference),
// and the compute lists held every fragment the raster pass met.
TEST(Visbuffer, BlendedSurfacesBothWaysWithinTheBound) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(256, 6);
    SceneGpu gpuScene(*ctx, scene);
    RunResult ref = runOrFail(*ctx, gpuScene, "reference", small(1));
    RunResult ref4 = runOrFail(*ctx, gpuScene, "reference", small(4, "sample"));
    RenderSettings centre = small(4, "pixel");
    centre.set("reference-msaa", "center");
    RunResult refCentre = runOrFail(*ctx, gpuScene, "reference", centre);
    for (const char* mode : {"compute", "forward"}) {
        const std::string m = std::string(" --vis-blended ") + mode;
        auto with = [&](RenderSettings s) {
            s.set("vis-blended", mode);
            return s;
        };
        RunResult one = runOrFail(*ctx, gpuScene, "visbuffer", with(small(1)));
        expectWithinBound(*ctx, scene, one, ref, with(small(1)), "1x" + m);
        expectRunWithinBound(*ctx, gpuScene, scene, ref4, with(small(4, "sample")),
                             "4x sample rate" + m);
        expectWithinBound(*ctx, scene,
                          runOrFail(*ctx, gpuScene, "visbuffer", with(small(4, "pixel"))),
                          refCentre, with(small(4, "sample")), "4x pixel rate" + m);
        if (std::string(mode) == "compute") {
            const double met = counterValue(one, "blended_fragments", -1);
            EXPECT_GT(met, 0.0) << "the courtyard's glass is on screen";
            EXPECT_EQ(counterValue(one, "blended_fragments_dropped", -1), 0.0);
            EXPECT_GE(counterValue(one, "blended_list_capacity"), met);
        } else {
            EXPECT_EQ(counterValue(one, "blended_fragments", -1), -1.0) << "no lists";
        }
    }
    expectNoValidationMessages(*ctx);
}

// More lights than one lighting batch holds (--light-cull all: every light a candidate; a
// batch is 1,638 lights at tile 16 on a CPU device, 4,096 on a GPU): each batch composites its
// own lights' part, and the sum is the composite of the sums, within the bound.
TEST(Visbuffer, BlendedLightsAddUpOverLightingBatches) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(5000, 8);
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings s = small(1);
    s.set("light-cull", "all");
    RunResult ref = runOrFail(*ctx, gpuScene, "reference", small(1));
    RunResult vis = runOrFail(*ctx, gpuScene, "visbuffer", s);
    expectWithinBound(*ctx, scene, vis, ref, s, "5,000 lights in batches");
    EXPECT_GT(counterValue(vis, "blended_fragments"), 0.0);
    EXPECT_GE(counterValue(vis, "lighting_batches"), 2.0);
    expectNoValidationMessages(*ctx);
}

// A pool smaller than the fragments (1 % of the pixels): each fragment past it is counted,
// exactly the ones the pool could not take.
TEST(Visbuffer, AFullFragmentPoolIsCountedNeverSilent) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(4, 6);
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings s = small(1);
    s.set("vis-blended-capacity", "1");
    RunResult vis = runOrFail(*ctx, gpuScene, "visbuffer", s);
    const double met = counterValue(vis, "blended_fragments");
    const double capacity = counterValue(vis, "blended_list_capacity");
    EXPECT_EQ(capacity, double(96 * 64 / 100));
    ASSERT_GT(met, capacity) << "the glass makes more fragments than 1 % of the pixels";
    EXPECT_EQ(counterValue(vis, "blended_fragments_dropped"), met - capacity);
    expectNoValidationMessages(*ctx);
}

// The pool's bound clipped to the near plane (fragment_bound.h: viewFragmentBound). With the
// eye inside each cloth panel's box, looking along the courtyard, some of its triangles lie
// behind the eye: counted as the whole screen each, as the bound once did, the pool would be
// millions of nodes at 96x64; clipped, only what lies in front of the near plane counts, less
// than one screen here, and still at least every fragment the raster pass met (none dropped).
TEST(Visbuffer, FragmentBoundClipsTrianglesAtTheNearPlane) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(4, 6);
    SceneGpu gpuScene(*ctx, scene);
    const RenderSettings s = small(1); // a single view's plan
    const std::vector<const DrawItem*> cloth = gpuScene.drawList(DrawFilter::Blend);
    ASSERT_FALSE(cloth.empty());
    for (size_t i = 0; i < cloth.size() && i < 3; ++i) {
        const glm::vec3 centre = (cloth[i]->bounds.min + cloth[i]->bounds.max) * 0.5f;
        scene.camera.position = centre;
        scene.camera.target = centre + glm::vec3(0.3f, -0.1f, 1.0f);
        RunResult run = runOrFail(*ctx, gpuScene, "visbuffer", s); // sets the view
        const vis::DrawTable table = vis::makeDrawTable(gpuScene, true);
        const uint64_t view = vis::viewFragmentBound(gpuScene, table.blended, 96, 64, 1);
        const double met = counterValue(run, "blended_fragments", -1);
        SCOPED_TRACE("cloth draw " + std::to_string(i));
        std::printf("[ visbuffer ] eye in cloth %zu: %.0f fragments met, bound %llu clipped\n", i,
                    met, (unsigned long long)view);
        EXPECT_GT(met, 0.0) << "the eye is inside the panel's box, facing along it";
        EXPECT_GE(double(view), met);
        EXPECT_EQ(counterValue(run, "blended_fragments_dropped", -1), 0.0);
        EXPECT_LT(view, uint64_t(96 * 64)) << "no triangle behind the eye counts the screen";
        EXPECT_EQ(counterValue(run, "blended_list_capacity", -1), double(view));
    }
    expectNoValidationMessages(*ctx);
}

uint64_t entryBytes(const RunResult& run, const std::string& name) {
    for (const LedgerEntry& e : run.memory)
        if (e.tag.name == name) return e.requestedBytes;
    return 0;
}

// The visibility data is 4 bytes of id and 4 of depth per sample, and nothing G-buffer-like.
TEST(Visbuffer, LedgerHoldsEightBytesPerSample) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(4, 5);
    SceneGpu gpuScene(*ctx, scene);
    for (uint32_t msaa : {1u, 4u}) {
        RunResult r = runOrFail(*ctx, gpuScene, "visbuffer", small(msaa));
        const uint64_t samples = uint64_t(96) * 64 * msaa;
        EXPECT_EQ(entryBytes(r, "visibility_ids"), samples * 4) << msaa;
        EXPECT_EQ(msaa > 1 ? entryBytes(r, "visibility_depth_msaa") : entryBytes(r, "depth"),
                  samples * 4)
            << msaa;
        for (const LedgerEntry& e : r.memory)
            EXPECT_EQ(e.tag.name.find("gbuffer"), std::string::npos) << e.tag.name;
    }
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test

namespace tp::test {
namespace {

// Many views (a camera path, the viewer): the fragment pool is sized from what views need, not
// from the bound (docs/visbuffer.md, "Many views"). A first view that sees almost no glass
// plans a pool of its bound; the next view meets more fragments than that, drops some, and
// the session renders it again with twice what it met: counted as a replan, nothing dropped
// in the kept image, which is bit for bit that of a renderer planned at that view.
TEST(Visbuffer, ManyViewsPoolGrowsOnACountedOverflow) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(4, 6);
    const Camera seeing = scene.camera;
    Camera away = seeing;
    away.target = away.position + (away.position - seeing.target); // the other way
    RenderSettings s = small(1);
    s.manyViews = true;
    Result<const RendererEntry*> entry = findRenderer("visbuffer");
    ASSERT_TRUE(entry.ok());
    scene.camera = away;
    SceneGpu gpu(*ctx, scene);
    auto session = RendererSession::create(*ctx, gpu, **entry, analyzeScene(scene, 1), s);
    ASSERT_TRUE(session.ok()) << session.error();
    RunOptions once;
    once.warmupFrames = 0;
    once.timedFrames = 1;
    Result<RunResult> first = (*session)->render(once);
    ASSERT_TRUE(first.ok()) << first.error();
    const double pool = first->stats.counter("blended_list_capacity");

    scene.camera = seeing;
    Result<RunResult> grown = (*session)->render(once);
    ASSERT_TRUE(grown.ok()) << grown.error();
    const double met = grown->stats.counter("blended_fragments");
    std::printf("[ visbuffer ] first view's pool %.0f nodes; the next view met %.0f, pool %.0f\n",
                pool, met, grown->stats.counter("blended_list_capacity"));
    ASSERT_GT(met, pool) << "the second view needs more than the first view's pool";
    EXPECT_EQ(grown->stats.counter("blended_fragments_dropped", -1), 0.0);
    EXPECT_GE(grown->stats.counter("blended_list_capacity"), met);
    EXPECT_EQ((*session)->replans(), 1u) << "the overflow is counted";
    EXPECT_EQ(grown->stats.counter("view_replans"), 1.0);

    SceneGpu fresh(*ctx, scene);
    auto there = RendererSession::create(*ctx, fresh, **entry, analyzeScene(scene, 1), s);
    ASSERT_TRUE(there.ok()) << there.error();
    Result<RunResult> want = (*there)->render(once);
    ASSERT_TRUE(want.ok()) << want.error();
    EXPECT_EQ(0, std::memcmp(grown->hdr.rgba.data(), want->hdr.rgba.data(),
                             want->hdr.rgba.size() * sizeof(float)));
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
