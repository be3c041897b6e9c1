// Shadows in the tiled compute lighting (deferred's --deferred-lighting tiled, the visibility
// buffer's resolve) and in the blended surfaces they shade (deferred's transparent_forward,
// the visibility buffer's compute composite and its forward pass): the shadow atlas
// (ShadowMaps::Residency::Atlas) sampled through evalLightShadowed, the maps and the filter
// Forward+ samples. courtyard-small (textured, masked, blended cloth) at 160x90, 8 lights,
// --shadows all, validation on.
//
// What is compared is what the shadows take away: d = none - all, per pixel and channel, for
// the pipeline (dP) and for Forward+ (dF). With the same maps, the same faces and the same
// PCF taps, every light's term is multiplied by the same visibility v in both pipelines, so
// dP - dF = sum over lights of (1 - v) (p - f), where p - f is one light's term's difference
// between the two architectures (G-buffer encoding, position from depth, the visibility
// buffer's barycentrics, Forward+'s fp16 target). The bound, per pixel and channel:
//   |dP - dF| <= a * |dF| + 2^-9 * F_none + 1e-6
// a: the architectures' relative difference, the largest of the pipeline against Forward+
// without shadows over channels above 1e-3 (lavapipe: deferred 3.3%, the visibility buffer
// 19.7%, at a few pixels; at least 2%: one light's term can differ more than a sum in which
// the lights' differences cancel); 2^-9: Forward+'s RGBA16F roundings of F_all and F_none.
// Also in sum: the light the shadows remove over the image within 1% of Forward+'s.
// A PCF tap that compares the other way in one pipeline moves 1/9 of a light's term: outside
// the bound where that light dominates. A depth comparison is a step, so any difference in
// the shaded position, however small, flips a tap whose stored depth lies between the two
// positions' depths; the chance is proportional to that difference (on lavapipe no pixel; on
// an H200, whose rasterizer snaps vertices before the depth plane, 1 pixel of deferred's 2,403
// shadowed and 3 of the visibility buffer's). So at most 0.5 % of the shadowed pixels may be
// beyond the bound, each by at most F_none (a tap moves at most all of a light's term).
// Shadow code disabled in the pipeline (dP = 0 where dF is not): the test fails (all the
// shadowed pixels beyond; checked when it was added: docs/deferred.md, "Shadows").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/image/metrics.h"
#include "core/scene/lights.h"
#include "core/scene/procedural.h"
#include "gpu_test_util.h"

namespace tp::test {
namespace {

constexpr double kArchRelative = 0.02; // a's floor

RenderSettings settings160x90(bool shadows) {
    RenderSettings s;
    s.width = 160;
    s.height = 90;
    s.shadows.all = shadows;
    return s;
}

struct ShadowEffect {
    double worstBeyond = 0; // the largest |dP - dF| beyond the bound (0: within)
    size_t worstPixel = 0;
    size_t pixelsBeyond = 0;
    double worstFlip = 0; // the largest |dP - dF| / F_none where beyond the bound (at most 1)
    double archRelative = 0;
    size_t shadowedPixels = 0; // pixels where Forward+'s shadows took away more than 1%
    double removedF = 0, removedP = 0; // sums of dF and dP over every pixel and channel
};

// The largest relative difference of the pipeline against Forward+ without shadows, over the
// channels brighter than 1e-3 (darker ones are within the absolute term): how far one light's
// term may differ between the two architectures.
double architectureRelative(const ImageRGBA& pNone, const ImageRGBA& fNone) {
    double worst = 0;
    for (size_t k = 0; k < fNone.rgba.size(); ++k)
        if (k % 4 != 3 && fNone.rgba[k] > 1e-3f)
            worst = std::max(worst,
                             std::abs(double(pNone.rgba[k]) - fNone.rgba[k]) / fNone.rgba[k]);
    return worst;
}

ShadowEffect compareEffects(const ImageRGBA& pAll, const ImageRGBA& pNone, const ImageRGBA& fAll,
                            const ImageRGBA& fNone) {
    ShadowEffect e;
    const double archRelative = std::max(kArchRelative, architectureRelative(pNone, fNone));
    e.archRelative = archRelative;
    for (size_t i = 0; i < fNone.pixelCount(); ++i) {
        bool shadowed = false, beyondAny = false;
        for (int c = 0; c < 3; ++c) {
            const size_t k = i * 4 + c;
            const double dF = double(fNone.rgba[k]) - fAll.rgba[k];
            const double dP = double(pNone.rgba[k]) - pAll.rgba[k];
            e.removedF += dF;
            e.removedP += dP;
            shadowed = shadowed || dF > 0.01 * fNone.rgba[k];
            const double bound =
                archRelative * std::abs(dF) + std::ldexp(1.0, -9) * fNone.rgba[k] + 1e-6;
            const double beyond = std::abs(dP - dF) - bound;
            beyondAny = beyondAny || beyond > 0;
            if (beyond > 0)
                e.worstFlip = std::max(e.worstFlip,
                                       std::abs(dP - dF) / std::max(double(fNone.rgba[k]), 1e-6));
            if (beyond > e.worstBeyond) {
                e.worstBeyond = beyond;
                e.worstPixel = i;
            }
        }
        e.shadowedPixels += shadowed;
        e.pixelsBeyond += beyondAny;
    }
    return e;
}

// courtyard-small with 8 lights that reach far enough to cast shadows across its courtyard
// (the generator's default ranges, 4-12% of the diagonal, shadow a few dozen pixels at this
// size), three point lights to a spot.
Scene courtyardWithReachingLights() {
    Result<Scene> s = makeBuiltinScene("courtyard-small");
    EXPECT_TRUE(s.ok());
    if (!s.ok()) return {};
    LightGenOptions o;
    o.count = 8;
    o.seed = 3;
    const float diagonal = glm::length(s->bounds.extent());
    o.radiusMin = 0.15f * diagonal;
    o.radiusMax = 0.3f * diagonal;
    o.pointWeight = 3.0f;
    o.spotWeight = 1.0f;
    s->lights = generateLights(s->bounds, o);
    return std::move(*s);
}

double counterOf(const RunResult& r, const std::string& name) {
    for (const auto& [n, v] : r.stats.counters)
        if (n == name) return v;
    return -1.0;
}

void expectShadowsAsForwardPlus(GpuContext& ctx, SceneGpu& scene, const std::string& pipeline,
                                const RenderSettings& knobs, const RunResult& fAll,
                                const RunResult& fNone) {
    SCOPED_TRACE(pipeline);
    RenderSettings on = settings160x90(true), off = settings160x90(false);
    on.knobs = off.knobs = knobs.knobs;
    const RunResult pAll = runOrFail(ctx, scene, pipeline, on);
    const RunResult pNone = runOrFail(ctx, scene, pipeline, off);
    ASSERT_EQ(pAll.hdr.pixelCount(), fAll.hdr.pixelCount());
    EXPECT_EQ(countNonFinitePixels(pAll.hdr), 0u);
    const ShadowEffect e = compareEffects(pAll.hdr, pNone.hdr, fAll.hdr, fNone.hdr);
    const size_t w = e.worstPixel;
    std::printf("[ shadows ] %-18s %zu shadowed pixels, removed %.4g (Forward+ %.4g), "
                "architecture %.3g relative, worst beyond the bound %.3g at (%zu, %zu), %zu pixels "
                "beyond (flipped taps, worst %.3g of F_none)\n",
                (pipeline + (knobs.knobs.empty() ? "" : " " + knobs.knobs.begin()->second)).c_str(),
                e.shadowedPixels, e.removedP, e.removedF, e.archRelative, e.worstBeyond, w % 160,
                w / 160, e.pixelsBeyond, e.worstFlip);
    // Not vacuous: a pipeline that drops its shadows (dP = 0) is far outside.
    EXPECT_LT(e.archRelative, 0.25);
    // The shadows darken a visible part of the image (not a vacuous comparison).
    EXPECT_GT(e.shadowedPixels, 1000u);
    EXPECT_NEAR(e.removedP, e.removedF, 0.01 * e.removedF);
    auto rgb = [w](const RunResult& r) {
        return std::to_string(r.hdr.rgba[w * 4]) + " " + std::to_string(r.hdr.rgba[w * 4 + 1]) +
               " " + std::to_string(r.hdr.rgba[w * 4 + 2]);
    };
    EXPECT_LE(e.pixelsBeyond, e.shadowedPixels / 200)
        << "pixel (" << w % 160 << ", " << w / 160 << "), " << e.pixelsBeyond
        << " pixels beyond: none " << rgb(pNone) << ", all " << rgb(pAll) << "; Forward+ none "
        << rgb(fNone) << ", all " << rgb(fAll);
    EXPECT_LE(e.worstFlip, 1.0) << "a flipped tap moves at most one light's whole term";
    // The atlas is cached (--shadow-cache on, the default): rendered once, outside the frames,
    // with no frame pass; its one-time cost is in the stats.
    EXPECT_EQ(counterOf(pAll, "shadowed_lights"), 8.0);
    EXPECT_EQ(counterOf(pAll, "shadow_maps_cached"), 1.0);
    EXPECT_EQ(counterOf(pAll, "shadow_maps_renders"), 1.0);
    EXPECT_EQ(counterOf(pAll, "shadow_map_renders_per_frame"), 0.0);
    EXPECT_FALSE(ranPass(pAll, "shadow_maps"));
    EXPECT_FALSE(ranPass(pNone, "shadow_maps")); // without --shadows nothing of it is planned
    EXPECT_EQ(counterOf(pNone, "shadowed_lights"), -1.0);
}

TEST(TiledShadows, SampleTheAtlasAsForwardPlusDoes) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardWithReachingLights();
    SceneGpu gpuScene(*ctx, scene);
    const RunResult fAll = runOrFail(*ctx, gpuScene, "forwardplus", settings160x90(true));
    const RunResult fNone = runOrFail(*ctx, gpuScene, "forwardplus", settings160x90(false));
    RenderSettings plain, forwardBlend;
    forwardBlend.set("vis-blended", "forward");
    expectShadowsAsForwardPlus(*ctx, gpuScene, "deferred", plain, fAll, fNone);
    expectShadowsAsForwardPlus(*ctx, gpuScene, "visbuffer", plain, fAll, fNone);
    expectShadowsAsForwardPlus(*ctx, gpuScene, "visbuffer", forwardBlend, fAll, fNone);
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
