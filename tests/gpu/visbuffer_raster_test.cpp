// The visibility buffer's compute rasterizer (--vis-raster compute|hybrid; docs/visbuffer.md,
// "The compute rasterizer"), with validation on: against the reference within the bound the
// hardware path is held to (courtyard-small, 1x and 4x at the sample rate), and against the
// hardware path itself: the same id at nearly every pixel and, where the ids agree, a depth
// within a few ulps; its counters add up and the passes appear in the timings and work counts.
// Masked draws (their alpha test in compute) on the masked glTF scene, triangles the near
// plane cuts with the eye inside the courtyard's geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/scene/lights.h"
#include "visbuffer/vis_raster.h"
#include "gpu_test_util.h"

namespace tp::test {
namespace {

RenderSettings rasterSettings(const std::string& raster, uint32_t msaa = 1, bool debug = false) {
    RenderSettings s;
    s.width = 96;
    s.height = 64;
    s.msaa = msaa;
    s.debug = debug;
    s.set("msaa-shading", "sample");
    s.set("vis-raster", raster);
    return s;
}

// How one rasterizer's ids and depth agree with another's (1x: the ids exported by --debug).
struct Agreement {
    size_t pixels = 0, sameId = 0, geometryDiffers = 0;
    double worstUlps = 0;     // depth, where the ids agree
    double worstRelative = 0; // |d - d'| / d there
};

uint32_t floatUlps(float a, float b) {
    int32_t ia, ib;
    std::memcpy(&ia, &a, 4);
    std::memcpy(&ib, &b, 4);
    return uint32_t(std::abs(int64_t(ia) - int64_t(ib)));
}

Agreement agreement(const RunResult& a, const RunResult& b) {
    const ImageRGBA* ia = debugImageOf(a, "visibility_ids");
    const ImageRGBA* ib = debugImageOf(b, "visibility_ids");
    Agreement r;
    EXPECT_TRUE(ia && ib);
    if (!ia || !ib) return r;
    r.pixels = ia->pixelCount();
    for (size_t i = 0; i < r.pixels; ++i) {
        const float idA = ia->rgba[i * 4], idB = ib->rgba[i * 4];
        if ((idA == 0.0f) != (idB == 0.0f)) ++r.geometryDiffers;
        if (idA != idB) continue;
        ++r.sameId;
        const float da = a.depth.r[i], db = b.depth.r[i];
        r.worstUlps = std::max(r.worstUlps, double(floatUlps(da, db)));
        if (da > 0.0f) r.worstRelative = std::max(r.worstRelative, std::abs(double(da) - db) / da);
    }
    return r;
}

void printAgreement(const char* what, const Agreement& g) {
    std::printf("[ vis-raster ] %-28s same id %.4f of %zu pixels (%zu differ in coverage), depth "
                "where the ids agree: %.0f ulps, %.3g relative\n",
                what, double(g.sameId) / double(g.pixels), g.pixels, g.geometryDiffers,
                g.worstUlps, g.worstRelative);
}

// Measured on lavapipe 2026-11-29 at 96x64 (docs/visbuffer.md, "The compute rasterizer"): the
// share of pixels holding the hardware's id (compute 0.9998, hybrid 1, the masked scene 1),
// and the depth where they do: unclipped triangles within 15 ulps (hybrid clips none in compute;
// 3 on the masked scene), triangles the near plane cuts within 8.8e-5 of the depth (compute:
// its clipped vertices and the hardware's differ by their own rounding).
constexpr double kSameIdShare = 0.999;
constexpr double kDepthUlps = 64;            // no triangle clipped in compute
constexpr double kClippedDepthRelative = 2e-4; // compute mode: clipped ones too

TEST(VisbufferRaster, WithinTheReferenceBoundOnTheCourtyard) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(256, 3);
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings refSettings = rasterSettings("hardware");
    const RunResult ref = runOrFail(*ctx, gpuScene, "reference", refSettings);
    refSettings.msaa = 4;
    const RunResult ref4 = runOrFail(*ctx, gpuScene, "reference", refSettings);
    for (const char* raster : {"compute", "hybrid"}) {
        const std::string n = raster;
        const RenderSettings one = rasterSettings(raster), four = rasterSettings(raster, 4);
        expectVisbufferWithinBound(*ctx, scene, runOrFail(*ctx, gpuScene, "visbuffer", one), ref,
                                   one, n + " 1x");
        expectVisbufferWithinBound(*ctx, scene, runOrFail(*ctx, gpuScene, "visbuffer", four),
                                   ref4, four, n + " 4x sample rate");
    }
    // The culled meshlets as the triangles' source.
    RenderSettings culled = rasterSettings("compute");
    culled.set("cull-geometry", "frustum");
    expectVisbufferWithinBound(*ctx, scene, runOrFail(*ctx, gpuScene, "visbuffer", culled), ref,
                               culled, "compute, --cull-geometry frustum");
    expectNoValidationMessages(*ctx);
}

TEST(VisbufferRaster, IdsAndDepthAgreeWithTheHardwarePath) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(4, 3);
    SceneGpu gpuScene(*ctx, scene);
    const RunResult hw = runOrFail(*ctx, gpuScene, "visbuffer", rasterSettings("hardware", 1, true));
    for (const char* raster : {"compute", "hybrid"}) {
        const RunResult r = runOrFail(*ctx, gpuScene, "visbuffer", rasterSettings(raster, 1, true));
        const Agreement g = agreement(r, hw);
        printAgreement(raster, g);
        EXPECT_GE(double(g.sameId), kSameIdShare * double(g.pixels)) << raster;
        if (std::string(raster) == "hybrid")
            EXPECT_LE(g.worstUlps, kDepthUlps);
        else
            EXPECT_LE(g.worstRelative, kClippedDepthRelative);
    }
    RenderSettings culled = rasterSettings("compute", 1, true);
    culled.set("cull-geometry", "frustum");
    const Agreement g = agreement(runOrFail(*ctx, gpuScene, "visbuffer", culled), hw);
    printAgreement("compute, culled meshlets", g);
    EXPECT_GE(double(g.sameId), kSameIdShare * double(g.pixels));
    EXPECT_LE(g.worstRelative, kClippedDepthRelative);
    expectNoValidationMessages(*ctx);
}

// The alpha test in compute: the masked glTF scene's cut-outs where the hardware has them.
TEST(VisbufferRaster, MaskedDrawsAlphaTestedInCompute) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Result<Scene> scene = loadMaskedScene(4, 7);
    ASSERT_TRUE(scene) << scene.error();
    SceneGpu gpuScene(*ctx, *scene);
    const RunResult hw = runOrFail(*ctx, gpuScene, "visbuffer", rasterSettings("hardware", 1, true));
    const RunResult r = runOrFail(*ctx, gpuScene, "visbuffer", rasterSettings("compute", 1, true));
    const Agreement g = agreement(r, hw);
    printAgreement("compute, masked scene", g);
    EXPECT_GE(double(g.sameId), kSameIdShare * double(g.pixels));
    // The alpha test's texture level of detail is the hardware's (its quad's fine differences):
    // the cut-outs cover what the hardware's do (4 pixels differed with a forward difference
    // from each pixel, 0 now; one allowed for a texel at the cutoff).
    EXPECT_LE(g.geometryDiffers, 1u);
    EXPECT_LE(g.worstUlps, kDepthUlps);
    expectNoValidationMessages(*ctx);
}

// The counters add up, the passes are timed, and the report counts their triangles and atomics.
TEST(VisbufferRaster, PassesAreTimedAndTheirWorkCounted) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(4, 3);
    SceneGpu gpuScene(*ctx, scene);
    for (const char* raster : {"compute", "hybrid"}) {
        SCOPED_TRACE(raster);
        const RunResult r = runOrFail(*ctx, gpuScene, "visbuffer", rasterSettings(raster));
        const double all = r.stats.counter("raster_triangles", -1),
                     small = r.stats.counter("raster_triangles_small", -1),
                     listed = r.stats.counter("raster_triangles_listed", -1),
                     culled = r.stats.counter("raster_triangles_culled", -1);
        std::printf("[ vis-raster ] %-8s triangles %.0f: small %.0f, listed %.0f, culled %.0f, "
                    "clipped %.0f, atomics %.0f\n",
                    raster, all, small, listed, culled,
                    r.stats.counter("raster_triangles_clipped", -1),
                    r.stats.counter("raster_sample_atomics", -1));
        EXPECT_GT(small, 0);
        EXPECT_GT(listed, 0);
        EXPECT_EQ(small + listed + culled, all);
        const bool compute = std::string(raster) == "compute";
        for (const char* pass : {"vis_raster_clear", "vis_raster", "vis_raster_big"}) {
            const bool expected = compute || std::string(pass) != "vis_raster_big";
            const bool timed = std::any_of(r.timings.begin(), r.timings.end(),
                                           [&](const TimingStats& t) { return t.name == pass; });
            EXPECT_EQ(timed, expected) << pass;
        }
        double triangles = 0, atomics = 0;
        for (const PassWork& w : r.work) {
            triangles += w.opCount(PassOpWork::Kind::Triangles);
            atomics += w.opCount(PassOpWork::Kind::GlobalAtomics);
        }
        EXPECT_EQ(triangles, compute ? small + listed : small);
        EXPECT_GT(atomics, 0);
    }
    expectNoValidationMessages(*ctx);
}

// Hybrid mode: the hardware draws the listed triangles in the draws' triangle order (ids
// strictly ascending), whatever order vis_raster's workgroups ran in, so that its depth test's
// ties and its fragment counts are the same on every run (vis_raster_order.comp); the list is
// what vis_raster counted, at 1x and 4x.
TEST(VisbufferRaster, HybridDrawsTheListedTrianglesInDrawOrder) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(4, 3);
    SceneGpu gpuScene(*ctx, scene);
    for (uint32_t msaa : {1u, 4u}) {
        SCOPED_TRACE(msaa);
        const std::vector<std::vector<uint8_t>> got =
            exportedBuffers(*ctx, gpuScene, "visbuffer", rasterSettings("hybrid", msaa),
                            {"vis_raster_list", "vis_raster_hw_list"});
        ASSERT_GE(got[0].size(), TP_VR_LIST_HEADER * 4u);
        uint32_t listed = 0;
        std::memcpy(&listed, got[0].data() + TP_VR_COUNT_BIG * 4, 4);
        ASSERT_GT(listed, 1u);
        ASSERT_GE(got[1].size(), size_t(listed) * 16);
        std::vector<uint32_t> words(size_t(listed) * 4);
        std::memcpy(words.data(), got[1].data(), words.size() * 4);
        uint32_t descending = 0;
        for (uint32_t t = 1; t < listed; ++t)
            if (words[t * 4 + 3] <= words[(t - 1) * 4 + 3]) ++descending;
        EXPECT_EQ(descending, 0u) << "of " << listed << " listed triangles";
    }
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
