// --shadow-raster compute (core/passes/shadow_raster.h, docs/shadows.md "Rasterizing the maps
// in compute"): the faces' depth rasterized in compute from the culled meshlets, against the
// hardware's maps of the same cull. courtyard-small, 64 lights of the generator's default
// ranges, 16 shadowed (masked foliage among the casters), validation with synchronization
// validation on.
//
// The atlas, texel by texel: where both cover a texel the depth differs by at most
// kDepthUlps ulps (the two interpolate the same plane from the same clip positions, llvmpipe
// from its own setup; the snap and the fill rule are the hardware's); coverage differs only
// where a texel centre lies on or within rounding of an edge, a few texels along the
// silhouettes (bounded below as a share of the covered texels), and where the alpha test's
// texture footprint differs from the hardware's quad derivatives. An overflowing list of
// large triangles changes nothing: their meshlets' large triangles are rasterized again.
// The images: Forward+ (the kept atlas, and every frame's) and the visibility buffer (every
// frame's, 4x) with compute maps against the same pipeline with the hardware's, within a
// small number of pixels (a tap whose stored depth moved past the receiver's moves 1/9 of a
// light's term).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/passes/shadow_maps.h"
#include "core/renderer/renderer.h"
#include "gpu_test_util.h"

// Named: the GPU tests build as unity files, where other tests' anonymous helpers are visible.
namespace tp::test::shadow_raster {
namespace {

constexpr uint32_t kShadowedLights = 16;
// The largest depth difference where both show the same surface, in ulps: 2^-10 relative, at
// most the depth bias of a 2,048-texel face (one texel footprint, 2 / edge of the distance) and
// a 64th of a 32-texel face's. Measured on lavapipe: 6,588 (4e-4 relative), where a large or
// clipped triangle's plane is anchored at a vertex far outside its small face.
constexpr int64_t kDepthUlps = 8192;
// Texels covered by one rasterizer and not the other, or showing another surface (beyond
// kDepthUlps), at most this share of those both cover (measured: 58 of 72,449).
constexpr double kCoverageShare = 0.002;
// Pixels of an image that may differ from the hardware maps' image, at most this share of the
// pixels the shadows darken (measured: 1 of 274 for Forward+, 3 of 416 for the visibility
// buffer at 4x).
constexpr double kPixelShare = 0.02;

Scene shadowCourtyard() {
    return courtyardSmallWithLights(64, 3);
}

// The test's view: 96x54, the 16 lights of largest influence shadowed, the faces culled.
RenderSettings shadowedSettings(uint32_t msaa) {
    RenderSettings s;
    s.width = 96;
    s.height = 54;
    s.msaa = msaa;
    s.shadows.count = kShadowedLights;
    s.set("cull-geometry", "frustum");
    return s;
}

double counterIn(const std::vector<std::pair<std::string, double>>& counters,
                 const std::string& name) {
    for (const auto& [n, v] : counters)
        if (n == name) return v;
    return -1.0;
}

int64_t ulpsApart(float a, float b) {
    int32_t x, y;
    std::memcpy(&x, &a, 4);
    std::memcpy(&y, &b, 4);
    return std::abs(int64_t(x) - int64_t(y)); // both positive: their bits order as values
}

struct SceneWithPlan {
    std::unique_ptr<GpuContext> ctx;
    Scene scene;
    std::unique_ptr<SceneGpu> gpu;
};

SceneWithPlan planned() {
    SceneWithPlan s{makeValidatedContext(), shadowCourtyard(), nullptr};
    s.gpu = std::make_unique<SceneGpu>(*s.ctx, s.scene);
    s.gpu->setView(96, 54, 1);
    ShadowSettings settings;
    settings.count = kShadowedLights;
    settings.cache = false;
    planSceneShadows(*s.ctx, *s.gpu, settings);
    return s;
}

TEST(ShadowRaster, AtlasAsTheHardwares) {
    SceneWithPlan s = planned();
    ASSERT_EQ(s.gpu->shadowPlan().lights.size(), kShadowedLights);
    const ShadowAtlasRun hw = renderShadowAtlas(*s.ctx, *s.gpu, CullGeometry::Frustum, ShadowRaster::Hardware);
    const ShadowAtlasRun cs = renderShadowAtlas(*s.ctx, *s.gpu, CullGeometry::Frustum, ShadowRaster::Compute);
    expectNoValidationMessages(*s.ctx);
    ASSERT_EQ(hw.depth.r.size(), cs.depth.r.size());
    // Where both cover a texel: the same surface within kDepthUlps, or another surface (a
    // triangle's edge texel kept by one rasterizer, with something farther behind it in the
    // other): counted with the texels only one covers.
    size_t both = 0, onlyHw = 0, onlyCs = 0, same = 0, otherSurface = 0;
    int64_t worst = 0;
    for (size_t i = 0; i < hw.depth.r.size(); ++i) {
        const float a = hw.depth.r[i], b = cs.depth.r[i];
        if (a > 0 && b > 0) {
            ++both;
            same += a == b;
            const int64_t ulps = ulpsApart(a, b);
            if (ulps > kDepthUlps)
                ++otherSurface;
            else
                worst = std::max(worst, ulps);
        }
        onlyHw += a > 0 && !(b > 0);
        onlyCs += b > 0 && !(a > 0);
    }
    const double rasterized = counterIn(cs.counters, "shadow_raster_triangles");
    const double listed = counterIn(cs.counters, "shadow_raster_triangles_listed");
    std::printf("[ shadow raster ] atlas %ux%u: %zu texels covered by both (%zu the same bits, "
                "the rest within %lld ulps but %zu: another surface), %zu by the hardware only, "
                "%zu by compute only; %.0f triangles rasterized in compute (%.0f listed, %.0f "
                "clipped, %.0f overflow), %.0f of the cull's\n",
                hw.depth.width, hw.depth.height, both, same, (long long)worst, otherSurface,
                onlyHw, onlyCs,
                rasterized, listed, counterIn(cs.counters, "shadow_raster_triangles_clipped"),
                counterIn(cs.counters, "shadow_raster_triangles_overflow"),
                counterIn(cs.counters, "shadow_triangles_submitted"));
    EXPECT_GT(both, 10000u);
    EXPECT_LE(double(otherSurface + onlyHw + onlyCs), kCoverageShare * double(both));
    EXPECT_GT(rasterized, 0);
    EXPECT_GT(listed, 0);
    EXPECT_EQ(counterIn(cs.counters, "shadow_raster_triangles_overflow"), 0);
    // Every triangle the cull kept is accounted for: rasterized or culled (between texel
    // centres, zero area, beside its face).
    EXPECT_EQ(rasterized + counterIn(cs.counters, "shadow_raster_triangles_culled"),
              counterIn(cs.counters, "shadow_triangles_submitted"));
}

// A list of 8 large triangles: the rest overflow, their meshlets are listed instead and their
// large triangles rasterized from there, so the atlas is the default list's bit for bit.
TEST(ShadowRaster, ListOverflowDropsNothing) {
    SceneWithPlan s = planned();
    const ShadowAtlasRun full = renderShadowAtlas(*s.ctx, *s.gpu, CullGeometry::Frustum, ShadowRaster::Compute);
    const ShadowAtlasRun tiny = renderShadowAtlas(*s.ctx, *s.gpu, CullGeometry::Frustum, ShadowRaster::Compute, 8);
    expectNoValidationMessages(*s.ctx);
    const double overflow = counterIn(tiny.counters, "shadow_raster_triangles_overflow");
    std::printf("[ shadow raster ] a list of 8: %.0f listed, %.0f overflowed\n",
                counterIn(tiny.counters, "shadow_raster_triangles_listed"), overflow);
    const double listed = counterIn(full.counters, "shadow_raster_triangles_listed");
    EXPECT_EQ(counterIn(tiny.counters, "shadow_raster_triangles_listed"), listed);
    EXPECT_EQ(overflow, listed - 8) << "all but 8 large triangles overflow";
    EXPECT_GT(overflow, 0);
    EXPECT_EQ(counterIn(tiny.counters, "shadow_raster_triangles"),
              counterIn(full.counters, "shadow_raster_triangles"));
    EXPECT_EQ(tiny.depth.r, full.depth.r) << "an overflowing list changed the atlas";
}

struct ImageCase {
    std::string pipeline;
    bool cache = true;
    uint32_t msaa = 1;
};

void expectCloseToHardwareMaps(const ImageCase& c) {
    const std::string what = c.pipeline + (c.cache ? "" : " --shadow-cache off") + " " +
                             std::to_string(c.msaa) + "x";
    SCOPED_TRACE(what);
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = shadowCourtyard();
    SceneGpu gpu(*ctx, scene);
    RenderSettings s = shadowedSettings(c.msaa);
    s.shadows.cache = c.cache;
    RenderSettings none = s;
    none.shadows = {};
    const RunResult unshadowed = runOrFail(*ctx, gpu, c.pipeline, none);
    const RunResult hw = runOrFail(*ctx, gpu, c.pipeline, s);
    s.set("shadow-raster", "compute");
    const RunResult cs = runOrFail(*ctx, gpu, c.pipeline, s, 2);
    expectNoValidationMessages(*ctx);
    const size_t shadowed = differingPixels(unshadowed.hdr, hw.hdr);
    const size_t differ = differingPixels(hw.hdr, cs.hdr);
    double worst = 0; // the largest difference relative to the unshadowed pixel
    for (size_t k = 0; k < hw.hdr.rgba.size(); ++k)
        if (k % 4 != 3)
            worst = std::max(worst, std::abs(double(hw.hdr.rgba[k]) - cs.hdr.rgba[k]) /
                                        std::max(1e-6, double(unshadowed.hdr.rgba[k])));
    std::printf("[ shadow raster ] %s: %zu of %zu pixels differ from the hardware maps' image "
                "(%zu shadowed), the worst by %.3g of the unshadowed pixel\n",
                what.c_str(), differ, hw.hdr.pixelCount(), shadowed, worst);
    EXPECT_GT(shadowed, 50u) << "the shadows must show, or the test holds whatever the maps hold";
    EXPECT_LE(double(differ), kPixelShare * double(shadowed));
    EXPECT_LE(worst, 1.0) << "a changed tap moves at most a light's whole term";
    EXPECT_EQ(hw.depth.r, cs.depth.r) << "the maps changed the camera's depth";
    EXPECT_GT(cs.stats.counter("shadow_raster_triangles", -1), 0);
}

TEST(ShadowRaster, ForwardPlusKeptAtlasCloseToHardware) {
    expectCloseToHardwareMaps({"forwardplus", true, 1});
}
TEST(ShadowRaster, ForwardPlusAtlasEveryFrameCloseToHardware) {
    expectCloseToHardwareMaps({"forwardplus", false, 1});
}
TEST(ShadowRaster, VisbufferAtlasEveryFrameCloseToHardwareMsaa4) {
    expectCloseToHardwareMaps({"visbuffer", false, 4});
}

// What it cannot do, refused with one line: one light's map, and no cull to rasterize.
TEST(ShadowRaster, RefusedWhereItCannotRun) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = shadowCourtyard();
    SceneGpu gpu(*ctx, scene);
    RenderSettings s = shadowedSettings(1);
    s.set("cull-geometry", "none");
    s.set("shadow-raster", "compute");
    RunOptions once;
    once.warmupFrames = 0;
    once.timedFrames = 1;
    auto run = [&](const std::string& pipeline, const RenderSettings& settings) {
        Result<const RendererEntry*> entry = findRenderer(pipeline);
        EXPECT_TRUE(entry.ok());
        return runRenderer(*ctx, gpu, **entry, analyzeScene(scene, 1), settings, once);
    };
    Result<RunResult> noCull = run("forwardplus", s);
    ASSERT_FALSE(noCull.ok());
    EXPECT_NE(noCull.error().find("--cull-geometry frustum"), std::string::npos) << noCull.error();
    s.set("cull-geometry", "frustum");
    Result<RunResult> perLight = run("multipass_forward", s);
    ASSERT_FALSE(perLight.ok());
    EXPECT_NE(perLight.error().find("--shadow-raster hardware"), std::string::npos)
        << perLight.error();
    EXPECT_EQ(perLight.error().find('\n'), std::string::npos) << "one line";
}

} // namespace
} // namespace tp::test::shadow_raster
