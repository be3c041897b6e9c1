// Deferred's light volumes with shadows (--deferred-lighting volumes --shadows, docs/deferred.md
// "Shadows"): one light's map at a time (ShadowMaps::Residency::PerLight), rendered right
// before that light's volume, against Forward+, which samples the same faces resident in its
// atlas. Validation (with synchronization validation) on: the per-light map is rendered,
// sampled and rendered over inside one pass, behind barriers of its own.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gpu_test_util.h"

namespace tp::test {
namespace {

// courtyard-small with its blended cloth made opaque: blended surfaces of a volumes run are
// lit by the hybrid forward pass (core/passes/hybrid_blended), not by the volumes, so they are
// left out of what this test checks.
Scene opaqueCourtyard(uint32_t lights) {
    Scene s = courtyardSmallWithLights(lights, 11);
    for (Material& m : s.materials)
        if (m.alphaMode == AlphaMode::Blend) m.alphaMode = AlphaMode::Opaque;
    return s;
}

RenderSettings settings(const char* pipeline, uint32_t msaa, bool shadows) {
    RenderSettings s;
    s.width = 160;
    s.height = 90;
    s.msaa = msaa;
    s.shadows.all = shadows;
    if (std::string(pipeline) == "deferred") {
        s.set("deferred-lighting", "volumes");
        s.set("gbuffer", "wide"); // fp32 material and normal: Forward+'s inputs, unrounded
    }
    return s;
}

double counter(const RunResult& run, const std::string& name) {
    for (const auto& [n, v] : run.stats.counters)
        if (n == name) return v;
    return -1.0;
}

// What the shadows did in one pipeline and how far the two pipelines' shadowed images are apart
// beyond their unshadowed ones' agreement (the comparison the test's comment derives).
struct ShadowComparison {
    double removedShare = 0; // light the shadows removed from the volumes image, of its total
    double darkenedShare = 0; // pixels whose volumes value lost more than 1 % of its light
    double excessShare = 0;   // pixels beyond the per-pixel bound
    double excessOfRemoved = 0; // the excess summed, of the light Forward+'s shadows removed
    double worstExcess = 0;
};

ShadowComparison compare(const RunResult& v0, const RunResult& vs, const RunResult& f0,
                         const RunResult& fs) {
    const double fp16 = std::ldexp(1.0, -10), floor = std::ldexp(1.0, -24);
    ShadowComparison c;
    double total = 0, removed = 0, removedForward = 0, excess = 0;
    size_t darkened = 0, over = 0;
    const size_t n = v0.hdr.pixelCount();
    for (size_t i = 0; i < n; ++i) {
        double lost = 0, before = 0, pixelExcess = 0;
        for (int ch = 0; ch < 3; ++ch) {
            const size_t k = i * 4 + ch;
            const double a0 = v0.hdr.rgba[k], as = vs.hdr.rgba[k];
            const double b0 = f0.hdr.rgba[k], bs = fs.hdr.rgba[k];
            total += a0;
            removed += a0 - as;
            removedForward += b0 - bs;
            lost = std::max(lost, a0 - as);
            before = std::max(before, a0);
            const double bound = std::abs(a0 - b0) + fp16 * std::max({a0, b0, as, bs}) + floor;
            pixelExcess = std::max(pixelExcess, std::abs(as - bs) - bound);
        }
        if (lost > 0.01 * before) ++darkened;
        if (pixelExcess > 0) {
            ++over;
            excess += pixelExcess;
            c.worstExcess = std::max(c.worstExcess, pixelExcess);
        }
    }
    c.removedShare = total > 0 ? removed / total : 0;
    c.darkenedShare = double(darkened) / double(n);
    c.excessShare = double(over) / double(n);
    c.excessOfRemoved = removedForward > 0 ? excess / removedForward : 0;
    return c;
}

// The floor and its box under two point lights low enough for the box to cast long shadows,
// a spot (one face) over it and a dim directional light (never shadowed).
Scene floorWithShadowCasters() {
    std::vector<Light> lights(4);
    lights[0].position = {-2.5f, 1.5f, -0.5f};
    lights[0].range = 9.0f;
    lights[0].intensity = 6.0f;
    lights[0].color = {1.0f, 0.8f, 0.6f};
    lights[1].position = {2.2f, 0.8f, 1.8f};
    lights[1].range = 7.0f;
    lights[1].intensity = 4.0f;
    lights[1].color = {0.6f, 0.8f, 1.0f};
    lights[2].type = LightType::Spot;
    lights[2].position = {0.5f, 3.0f, -3.0f};
    lights[2].direction = glm::normalize(glm::vec3(-0.2f, -3.0f, 4.5f));
    lights[2].range = 10.0f;
    lights[2].intensity = 12.0f;
    lights[2].innerConeAngle = 0.3f;
    lights[2].outerConeAngle = 0.6f;
    lights[3].type = LightType::Directional;
    lights[3].direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.2f));
    lights[3].intensity = 0.05f;
    return makeFloorScene(lights);
}

// Per pixel and channel, with v / f the volumes / Forward+ images without (0) and with (s)
// shadows: |vs - fs| <= |v0 - f0| + 2^-10 max(v0, f0, vs, fs) + 2^-24.
//  - Both shadow the same lights with the same faces, filter and bias (shadow_sample.glsl);
//    only where the maps live differs (one light's map here, the atlas there: the same texels).
//    A pixel's value is sum_l c_l V_l with V_l in [0, 1] the light's visibility; where the two
//    pipelines get the same V_l, their difference is sum_l (c_l - c'_l) V_l, at most
//    sum_l |c_l - c'_l|, which is |v0 - f0| when the terms differ in one direction (the
//    G-buffer's reconstructed position against the interpolated one moves every light alike).
//  - Forward+ stores RGBA16F: f0 and fs are each rounded to 2^-11 of their value (2^-24: its
//    subnormal spacing); the wide G-buffer and deferred's RGBA32F hdr round far less.
// What can exceed it: a PCF tap whose comparison flips because the receiver is not at exactly
// the same position (reconstructed from D32 depth against interpolated; under MSAA, deferred
// lights edge pixels per sample where Forward+ shades once per pixel), a ninth of one light's
// term per tap. Allowed on kFlipPixels of the pixels and kFlipLight of the light Forward+'s
// shadows remove; measured on lavapipe at 160 x 90: none at 1x, 0.18 % of the pixels and 0.03 % of the
// removed light at 4x (the floor).
constexpr double kFlipPixels = 0.01, kFlipLight = 0.01;
// The shadows must act: at least kDarkened of the pixels lose more than 1 % of their light
// (measured: 13 % on the floor, 9.4 % on the courtyard; 0 with the shadow code disabled).
constexpr double kDarkened = 0.05;

void checkScene(GpuContext& ctx, const Scene& scene, const std::string& name,
                const std::vector<uint32_t>& rates) {
    SceneGpu gpuScene(ctx, scene);
    for (uint32_t msaa : rates) {
        const std::string what = name + ", " + std::to_string(msaa) + "x";
        RunResult v0 = runOrFail(ctx, gpuScene, "deferred", settings("deferred", msaa, false));
        RunResult vs = runOrFail(ctx, gpuScene, "deferred", settings("deferred", msaa, true));
        RunResult f0 = runOrFail(ctx, gpuScene, "forwardplus", settings("forwardplus", msaa, false));
        RunResult fs = runOrFail(ctx, gpuScene, "forwardplus", settings("forwardplus", msaa, true));
        ASSERT_TRUE(ranPass(vs, "volume_shadowed_lights")) << what;
        EXPECT_FALSE(ranPass(v0, "volume_shadowed_lights")) << what;
        ShadowComparison c = compare(v0, vs, f0, fs);
        std::printf("[ volume shadows ] %s: %.0f lights shadowed, map %.0f bytes (atlas %.0f); "
                    "removed %.3g of the light, %.3g of pixels darkened; beyond the bound: %.3g "
                    "of pixels, %.3g of the removed light, worst %.3g\n",
                    what.c_str(), counter(vs, "shadowed_lights"), counter(vs, "shadow_map_bytes"),
                    counter(fs, "shadow_map_bytes"), c.removedShare, c.darkenedShare,
                    c.excessShare, c.excessOfRemoved, c.worstExcess);
        EXPECT_GE(c.darkenedShare, kDarkened) << what << ": the shadows darken too little";
        EXPECT_LE(c.excessShare, kFlipPixels) << what << ": pixels beyond Forward+'s shadows";
        EXPECT_LE(c.excessOfRemoved, kFlipLight) << what << ": light beyond Forward+'s shadows";
        // One map, rendered once per shadowed light; the atlas holds them all.
        EXPECT_EQ(counter(vs, "shadow_map_renders_per_frame"), counter(vs, "shadowed_lights"));
        EXPECT_LT(counter(vs, "shadow_map_bytes"), counter(fs, "shadow_map_bytes")) << what;
    }
}

TEST(VolumeShadows, MatchForwardPlusShadowsOneMapAtATime) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    checkScene(*ctx, floorWithShadowCasters(), "floor and box, 4 lights", {1u, 4u});
    checkScene(*ctx, opaqueCourtyard(16), "courtyard-small opaque, 16 lights", {1u});
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
