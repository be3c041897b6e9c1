// The visibility buffer's two fidelity knobs against the rasterizer (docs/visbuffer.md):
// --vis-derivatives (the texture footprint: quad differences as a fragment quad takes them,
// or the analytic derivatives), and the shaded position next to a light hugging a surface
// ("The position's error"), each against the reference, with Forward+ (a fragment stage, the
// reference's own interpolation and derivatives) as the yardstick.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/image/metrics.h"
#include "core/camera/pixel_position.h"
#include "core/renderer/renderer.h"
#include "core/scene/gltf_loader.h"
#include "core/scene/lights.h"
#include "core/scene/stress_scenes.h"
#include "gpu_test_util.h"
#include "include/light_model.h"
#include "include/shared.h"
#include "visbuffer/vis_settings.h"
#include "visbuffer/vis_shared.h"

namespace tp::test {
namespace {

RenderSettings fidelitySettings(uint32_t w, uint32_t h, const char* derivatives = nullptr) {
    RenderSettings s;
    s.width = w;
    s.height = h;
    if (derivatives) s.set("vis-derivatives", derivatives);
    return s;
}

double fidelityCounter(const RunResult& run, const std::string& name) {
    return run.stats.counter(name, -1.0);
}

struct FootprintErrors {
    ErrorReport forwardplus, quad, analytic;
};

void printFootprint(const char* name, const ErrorReport& e) {
    std::printf("    %-9s RMSE %.3g (worst pixel %u,%u holds %.0f %%; without it %.3g), mean "
                "relative %.3g\n",
                name, e.rmse, e.worstPixelX, e.worstPixelY, 100.0 * e.worstPixelShare,
                e.rmseWithoutWorstPixel, e.meanRelative);
}

// HDR errors against the reference of Forward+ and of the visibility buffer both ways.
FootprintErrors footprintErrors(GpuContext& ctx, const Scene& scene, uint32_t w, uint32_t h,
                                const std::string& what) {
    SceneGpu gpuScene(ctx, scene);
    const RunResult ref = runOrFail(ctx, gpuScene, "reference", fidelitySettings(w, h));
    FootprintErrors e;
    e.forwardplus =
        computeError(runOrFail(ctx, gpuScene, "forwardplus", fidelitySettings(w, h)).hdr, ref.hdr);
    const RunResult quad = runOrFail(ctx, gpuScene, "visbuffer", fidelitySettings(w, h, "quad"));
    EXPECT_EQ(fidelityCounter(quad, "uv_derivatives_mode"),
              double(vis::resolveDerivatives(vis::Derivatives::Quad)));
    e.quad = computeError(quad.hdr, ref.hdr);
    const RunResult analytic = runOrFail(ctx, gpuScene, "visbuffer", fidelitySettings(w, h, "analytic"));
    EXPECT_EQ(fidelityCounter(analytic, "uv_derivatives_mode"), double(TP_VIS_DERIVATIVES_ANALYTIC));
    e.analytic = computeError(analytic.hdr, ref.hdr);
    std::printf("[ footprint ] %s, HDR against the reference:\n", what.c_str());
    printFootprint("Forward+", e.forwardplus);
    printFootprint("quad", e.quad);
    printFootprint("analytic", e.analytic);
    return e;
}

TEST(VisbufferFootprint, TheKnobIsDeclaredWithItsValues) {
    const RendererEntry& entry = **findRenderer("visbuffer");
    for (const char* v : {"quad", "analytic", "quad-fine", "quad-coarse"}) {
        RenderSettings s = fidelitySettings(8, 8, v);
        EXPECT_TRUE(resolveKnobs(entry.knobs, s).ok()) << v;
    }
    RenderSettings bad = fidelitySettings(8, 8, "hardware");
    EXPECT_FALSE(resolveKnobs(entry.knobs, bad).ok());
    // llvmpipe takes coarse derivatives (the quad's top-left pixel), and coarse measured closest
    // on an H200 too (docs/visbuffer.md).
    EXPECT_EQ(vis::resolveDerivatives(vis::Derivatives::Quad), TP_VIS_DERIVATIVES_QUAD_COARSE);
    EXPECT_EQ(vis::resolveDerivatives(vis::Derivatives::QuadFine), TP_VIS_DERIVATIVES_QUAD_FINE);
}

// The target of issue 40: with the quad's differences the visibility buffer samples textures
// as the rasterizer does, within 2x Forward+'s error against the reference, where the
// analytic derivatives are not. The error is the mean relative one: a footprint error is
// spread over the textured surfaces, and the RMSE can be one pixel's next to a light, where
// the visibility buffer's position (not its footprint) decides (docs/visbuffer.md, "The
// position's error"). On an H200 (2026-11-28), courtyard-small: mean relative Forward+ 3.01e-4,
// quad 3.82e-4, analytic 2.6e-3; RMSE 1.43e-4, 1.91e-3 (pixel 78,26 holds 94 % of it),
// 2.71e-3. On lavapipe the quad's both figures are 1/100 of Forward+'s (its RGBA16F target). The
// built-in courtyard: every material textured (base colour, metal-rough, normal maps).
TEST(VisbufferFootprint, QuadDerivativesSampleTexturesAsTheRasterizer) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const FootprintErrors e = footprintErrors(*ctx, courtyardSmallWithLights(64, 11), 128, 72,
                                              "courtyard-small 64 lights");
    EXPECT_LE(e.quad.meanRelative, 2.0 * e.forwardplus.meanRelative);
    EXPECT_LT(e.quad.meanRelative, e.analytic.meanRelative);
    expectNoValidationMessages(*ctx);
}

// The same on the shared DamagedHelmet (all five texture slots), where the issue measured it.
TEST(VisbufferFootprint, QuadDerivativesOnTheDamagedHelmet) {
    const std::filesystem::path path =
        std::filesystem::path(TP_SHARED_SCENES) / "DamagedHelmet/glTF/DamagedHelmet.gltf";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent";
    Result<Scene> scene = loadGltf(path.string());
    ASSERT_TRUE(scene.ok()) << scene.error();
    LightGenOptions o;
    o.count = 64;
    o.seed = 11;
    scene->lights = generateLights(scene->bounds, o);
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const FootprintErrors e = footprintErrors(*ctx, *scene, 128, 72, "DamagedHelmet 64 lights");
    EXPECT_LE(e.quad.meanRelative, 2.0 * e.forwardplus.meanRelative);
    EXPECT_LT(e.quad.meanRelative, e.analytic.meanRelative);
    expectNoValidationMessages(*ctx);
}

// The shaded point next to a light hugging a surface (docs/visbuffer.md, "The position's
// error next to a light"). The stress case's floor (80 m, two triangles whose corners lie 45-70 m from the eye)
// seen from 2 m above it; in the middle column the pixel-centre rays have x = 0 exactly (the
// view's right axis is x), and seven of them, 13-44 m away, meet the floor 5 mm beside a light
// 0.1 mm above it (2 cm range: each light reaches its own pixel only). There n . l is about
// 0.02 and a point 1 um off the plane is 1% of the radiance. The truth is the light model on
// the CPU at the exact hit (y = -2 camera-relative, exact in fp32), so each pipeline's error is
// its own, not its difference from the reference's.
//
// The resolve moves the ray's hit onto the plane along the unit normal: for this floor the
// normal coordinate is then p0's exactly, and the point keeps the hit's place on the plane (x
// exactly 0 in the middle column; the hit's rounding along the ray moves it along z, across
// the light's 5 mm x offset, to second order). The test asks for what issue 40 does: at least
// as exact as the rasterizer's interpolation, the reference's (worst pixel against worst
// pixel). The ray's hit t * dir itself (before issue 40) failed: 1.18e-3 at one pixel, one ulp
// of y off the plane, against the reference's 3.6e-4 (docs/visbuffer.md, "The position's error
// next to a light").
TEST(VisbufferPosition, ALightHuggingAFarFloorSeesThePointOnTheSurface) {
    Scene scene = stress::lightHuggingFar();
    scene.lights.clear();
    scene.ambient = glm::vec3(0.0f);
    const uint32_t w = 95, h = 63, column = 47;
    const glm::dmat4 inverse = inverseShadingViewProjection(scene.camera, w, h);
    const glm::dvec3 eye(scene.camera.position);
    struct Hot {
        uint32_t row;
        glm::dvec3 hit; // camera-relative, on the floor (y = -eye.y)
    };
    std::vector<Hot> hot;
    for (uint32_t row : {27u, 28u, 29u, 30u, 31u, 33u, 35u}) {
        const glm::dvec3 a = pixelCentrePosition(inverse, w, h, column, row, 1.0);
        const glm::dvec3 b = pixelCentrePosition(inverse, w, h, column, row, 0.5);
        const double t = (-eye.y - a.y) / (b.y - a.y);
        const glm::dvec3 hit = a + t * (b - a);
        hot.push_back({row, hit});
        const glm::dvec3 world = hit + eye;
        scene.lights.push_back(stress::build::point({0.005f, 0.0001f, float(world.z)}, 1.0f, 0.02f));
    }
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    SceneGpu gpuScene(*ctx, scene);
    const RunResult ref = runOrFail(*ctx, gpuScene, "reference", fidelitySettings(w, h));
    const RunResult fp = runOrFail(*ctx, gpuScene, "forwardplus", fidelitySettings(w, h));
    const RunResult vis = runOrFail(*ctx, gpuScene, "visbuffer", fidelitySettings(w, h));
    double worstRef = 0, worstFp = 0, worstVis = 0;
    for (size_t k = 0; k < hot.size(); ++k) {
        gpu::SurfaceSample s;
        s.position = glm::vec3(hot[k].hit);
        s.normal = glm::vec3(0, 1, 0);
        s.toViewer = glm::normalize(-s.position);
        s.baseColor = glm::vec3(0.5f);
        s.metallic = 0.0f;
        s.roughness = 1.0f;
        gpu::LightGpu light = toGpu(scene.lights[k]);
        light.position = glm::vec3(glm::dvec3(scene.lights[k].position) - eye); // as uploaded
        const double truth = gpu::evalLight(light, s, false).x;
        ASSERT_GT(truth, 0.0);
        auto error = [&](const RunResult& r) {
            return std::abs(double(r.hdr.at(column, hot[k].row)[0]) - truth) / truth;
        };
        std::printf("[ position ] row %u at %.1f m: truth %.6g, reference %.3g, Forward+ %.3g, "
                    "visbuffer %.3g (relative)\n",
                    hot[k].row, glm::length(hot[k].hit), truth, error(ref), error(fp), error(vis));
        worstRef = std::max(worstRef, error(ref));
        worstFp = std::max(worstFp, error(fp));
        worstVis = std::max(worstVis, error(vis));
    }
    std::printf("[ position ] worst: reference %.3g, Forward+ %.3g, visbuffer %.3g\n", worstRef,
                worstFp, worstVis);
    // At least as exact as the rasterizer's interpolation (the reference's point; Forward+'s
    // figure carries its fp16 hdr's rounding too).
    EXPECT_LE(worstVis, worstRef);
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
