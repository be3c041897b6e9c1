// Multipass forward with --shadows (lavapipe, validation on): a map per light pass
// (docs/multipass_forward.md, "Shadows") against Forward+'s resident atlas.
//
// Both pipelines shadow the same lights with the same faces (SceneGpu's plan), render the
// same depths into them (the same vertex shader and projection; a face's viewport differs
// only by a whole-texel offset, atlas or one light's 3 x 2 block) and filter them with the
// same code (include/shadow_sample.glsl) at the same receiver positions. So each light's term
// is the same value in both, and what differs is the summation, as without shadows:
//   multipass   fp32 accumulation, one rounding per additive pass (n + 4 roundings, see
//               multipass_forward_test.cpp), 6 more per blended layer;
//   Forward+    sums in fp32 in the shader (n roundings), then one fp16 store of the result,
//               and one per blended layer composited in its RGBA16F target; each store is
//               below one ulp, 2^-10 relative (kHalfUlp16: Vulkan allows rounding toward
//               zero, and lavapipe does: measured, a full ulp below multipass here).
// All terms are >= 0, so per pixel and channel, with v = max(|mp|, |fp|) and L blended layers,
//     |mp - fp| <= ((1 + L) 2^-10 + (2 n + 8 + 6 L) 2^-24) v + (n + 1) 6e-8
// (6e-8: the spacing of fp16 below its normal range). A visibility that differed in one PCF
// tap of one light moves a pixel by 1/9 of that light's term, far beyond this bound.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/cli/shadow_option.h"
#include "core/renderer/error_model.h"
#include "gpu_test_util.h"

// Named: the GPU tests build as unity files, where other tests' anonymous helpers are visible.
namespace tp::test::mp_shadows {
namespace {

constexpr double kEps32 = 1.0 / 16777216.0; // 2^-24
constexpr double kTiny16 = 6.0e-8;

double counter(const RunResult& run, const std::string& name) {
    for (const auto& [k, v] : run.stats.counters)
        if (k == name) return v;
    ADD_FAILURE() << "no counter " << name;
    return -1;
}

struct Agreement {
    double worstRatio = 0; // max |mp - fp| / bound over pixels and channels
    size_t worstPixel = 0;
    double blendedWorstRatio = 0; // over the pixels a blended layer may cover
};

Agreement agreement(const ImageRGBA& mp, const ImageRGBA& fp, uint32_t lights,
                    const std::vector<uint32_t>& layers) {
    Agreement a;
    const double n = lights;
    for (size_t p = 0; p < fp.pixelCount(); ++p) {
        const double l = layers[p];
        for (int ch = 0; ch < 3; ++ch) {
            const double x = mp.rgba[p * 4 + ch], y = fp.rgba[p * 4 + ch];
            const double v = std::max(std::abs(x), std::abs(y));
            const double bound =
                ((1 + l) * kHalfUlp16 + (2 * n + 8 + 6 * l) * kEps32) * v + (n + 1) * kTiny16;
            const double r = std::abs(x - y) / bound;
            if (r > a.worstRatio) a.worstRatio = r, a.worstPixel = p;
            if (l > 0) a.blendedWorstRatio = std::max(a.blendedWorstRatio, r);
        }
    }
    return a;
}

// The share of pixels a shadow darkens: some channel lower than without shadows by more
// than 1% (shadows only ever remove light), over all pixels and over those a blended layer
// may cover.
struct Darkened {
    double share = 0, blendedShare = 0;
};

Darkened darkened(const ImageRGBA& shadowed, const ImageRGBA& plain,
                  const std::vector<uint32_t>& layers) {
    size_t dark = 0, blended = 0, blendedDark = 0;
    for (size_t p = 0; p < plain.pixelCount(); ++p) {
        bool d = false;
        for (int ch = 0; ch < 3; ++ch)
            d = d || shadowed.rgba[p * 4 + ch] < 0.99f * plain.rgba[p * 4 + ch];
        dark += d;
        blended += layers[p] > 0;
        blendedDark += d && layers[p] > 0;
    }
    return {double(dark) / double(plain.pixelCount()),
            blended ? double(blendedDark) / double(blended) : 0.0};
}

// courtyard-small (opaque, masked and blended draws) at 160 x 90, 8 lights, all shadowed: the
// per-light maps agree with Forward+'s atlas within the summation bound everywhere, blended
// surfaces included, and the shadows are there. The courtyard's ambient term dominates its 8
// lights (the shadows remove 0.9% of the image's energy, darken 1% of its pixels by more than
// 1%), so "there" is: some pixels darker, blended ones too, and the image without shadows
// far outside the bound around Forward+'s with them.
TEST(MultipassShadows, MatchForwardPlusAtlasOnCourtyard) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const uint32_t lights = 8;
    Scene scene = courtyardSmallWithLights(lights, 3);
    SceneGpu gpu(*ctx, scene);
    gpu.setLights(scene.lights);
    RenderSettings plain;
    plain.width = 160;
    plain.height = 90;
    RenderSettings shadowed = plain;
    shadowed.shadows = parseShadowCount("all");

    RunResult mp = runOrFail(*ctx, gpu, "multipass_forward", shadowed);
    const double localBytes = double(gpu.shadowPlan().localBytes());
    RunResult fp = runOrFail(*ctx, gpu, "forwardplus", shadowed);
    RunResult mpPlain = runOrFail(*ctx, gpu, "multipass_forward", plain);
    ASSERT_EQ(mp.hdr.rgba.size(), fp.hdr.rgba.size());
    ASSERT_EQ(mp.hdr.rgba.size(), mpPlain.hdr.rgba.size());
    const std::vector<uint32_t> layers = blendedLayers(scene, gpu.frame());

    const Agreement a = agreement(mp.hdr, fp.hdr, lights, layers);
    EXPECT_LE(a.worstRatio, 1.0) << "pixel " << a.worstPixel % 160 << ", " << a.worstPixel / 160;
    const Darkened d = darkened(mp.hdr, mpPlain.hdr, layers);
    EXPECT_GT(d.share, 0.005) << "the shadows are missing";
    EXPECT_GT(d.blendedShare, 0.005) << "blended surfaces receive no shadows";
    // Control: the same bound fails without shadows on one side (the test can tell).
    EXPECT_GT(agreement(mpPlain.hdr, fp.hdr, lights, layers).worstRatio, 10.0);

    // One light's map, rendered at least once per shadowed light that lights something.
    const double shadowedLights = counter(mp, "shadowed_lights");
    EXPECT_GT(shadowedLights, 0.0);
    EXPECT_EQ(counter(mp, "shadow_map_bytes"), localBytes);
    EXPECT_LT(counter(mp, "shadow_map_bytes"), counter(fp, "shadow_map_bytes"));
    EXPECT_EQ(counter(mp, "shadow_map_renders_per_frame"),
              counter(mp, "light_passes_shadow_renders") + counter(mp, "blended_shadow_renders"));
    EXPECT_LE(counter(mp, "light_passes_shadow_renders"), shadowedLights);
    EXPECT_GT(counter(mp, "light_passes_shadow_renders"), 0.0);
    std::printf("[   info   ] %.0f shadowed lights: worst/bound %.3g (blended pixels %.3g), "
                "darkened %.1f%% (blended pixels %.1f%%), map renders %.0f + %.0f blended\n",
                shadowedLights, a.worstRatio, a.blendedWorstRatio, 100 * d.share,
                100 * d.blendedShare, counter(mp, "light_passes_shadow_renders"),
                counter(mp, "blended_shadow_renders"));
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test::mp_shadows
