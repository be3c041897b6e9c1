// The G-buffer deferred pipeline on the default device (lavapipe in CI), validation on.
// Tolerances are derived in docs/deferred.md ("Accuracy"); the constants below repeat them.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <cstring>
#include <filesystem>
#include <unistd.h>

#include "core/gpu/frame_graph.h"
#include "core/gpu/ledger.h"
#include "core/gpu/readback.h"
#include "core/gpu/vk_check.h"
#include "core/image/metrics.h"
#include "core/passes/blended_bounds.h"
#include "core/scene/gltf_loader.h"
#include "core/scene/lights.h"
#include "core/scene/procedural.h"
#include "gltf_test_scenes.h"
#include "gpu_test_util.h"
#include "include/light_assign.h"
#include "include/lights_ubo.h"
#include "include/materials_ubo.h"
#include "triangle_pixels.h"

namespace tp::test {
namespace {

Scene floorWithLights(uint32_t count) {
    Scene s = makeFloorScene({});
    LightGenOptions o;
    o.count = count;
    o.seed = 7;
    s.lights = generateLights(s.bounds, o);
    if (count == 1) { // one light close to the box: specular and diffuse both visible
        s.lights[0].position = {1.5f, 1.2f, 1.5f};
        s.lights[0].range = 6.0f;
        s.lights[0].intensity = 8.0f;
    }
    return s;
}

Scene courtyardWithLights(uint32_t count) {
    return courtyardSmallWithLights(count, 11);
}

struct Pair {
    RunResult deferred, reference;
    ErrorReport error;
};

Pair renderBoth(GpuContext& ctx, const Scene& scene, RenderSettings settings) {
    SceneGpu gpuScene(ctx, scene);
    Pair p;
    p.deferred = runOrFail(ctx, gpuScene, "deferred", settings);
    p.reference = runOrFail(ctx, gpuScene, "reference", settings);
    p.error = computeError(p.deferred.hdr, p.reference.hdr);
    return p;
}

RenderSettings small(uint32_t msaa, const char* gbuffer) {
    RenderSettings s;
    s.width = 96;
    s.height = 64;
    s.msaa = msaa;
    s.set("gbuffer", gbuffer);
    return s;
}

// Largest |d - r| / (|r| + floor) over pixels (those `only` marks 1, when given) and RGB channels.
double maxRelativeError(const ImageRGBA& d, const ImageRGBA& r, double floor,
                        const std::vector<uint8_t>* only = nullptr) {
    double worst = 0.0;
    for (size_t i = 0; i < r.pixelCount(); ++i)
        for (int c = 0; c < 3 && (!only || (*only)[i]); ++c) {
            double a = d.rgba[i * 4 + c], b = r.rgba[i * 4 + c];
            worst = std::max(worst, std::abs(a - b) / (std::abs(b) + floor));
        }
    return worst;
}

std::string describe(const ErrorReport& e) {
    return "rmse " + std::to_string(e.rmse) + " maxAbs " + std::to_string(e.maxAbs) + " at " +
           std::to_string(e.maxAbsX) + "," + std::to_string(e.maxAbsY) + " meanRel " +
           std::to_string(e.meanRelative) + " nan " + std::to_string(e.nanInfCount);
}

// Two errors, measured apart (docs/deferred.md, "Position reconstruction and the reference"):
//  (a) deferred against the reference lit at the position deferred reconstructs from depth
//      (--reference-position depth: the same unprojection, include/unproject.glsl, of the same
//      depth): what deferred's own code adds, bounded by expectWithinTheDepthReferenceBound on
//      every device;
//  (b) the reconstruction error, that reference against the interpolated one: a property of
//      the device's rasterizer (how far the D32 depth's unprojection lands from the vertex
//      shader's interpolated position), not of deferred's code. Its bounds were measured on
//      lavapipe (where they are the old deferred-vs-reference bounds' source), so they are
//      asserted on a CPU device only and printed elsewhere: on an NVIDIA H100 (vertex
//      snapping to a subpixel grid, another interpolation) it was measured 3-30x larger.
RenderSettings withPosition(RenderSettings s, const char* position) {
    s.set("reference-position", position);
    return s;
}

// Deferred's image against the depth reference's, per channel: both evaluate every term with
// the same code on the same fp32 inputs (the wide G-buffer stores the material in fp32, the
// position is the same unprojection of the same D32 value), so what remains is
//  - the light sum: deferred adds N = samples * (lights + 1) non-negative terms in fp32 in its
//    list order (and the MSAA resolve's average), the reference in fp64 (rounded once to fp32:
//    u / 2): at most (N - 1) u + u / 2 of the sum (Higham, recursive summation), u = 2^-24;
//  - the ambient term, multiplied in another association (base * (1 - metallic) first in
//    material.glsl, ambient * base first in gbuffer_read.glsl): 3 roundings a side, 6 u;
//  - fp32 evaluation of a light term by two compilations of the same code (the compiler may
//    fuse a multiply-add in one and not the other): a few u per term, K u of the sum.
// Bound: (2 (N - 1) + 6 + K) u * max(|d|, |r|) + 1e-30, K = 8 (4 roundings a term on either
// side). The pixels compared can be restricted by `only` (1 = compare). Returns the worst
// |d - r| / bound, asserted <= 1 and printed with the worst relative error.
constexpr double kEvaluationUlps = 8.0;

double expectWithinTheDepthReferenceBound(const ImageRGBA& d, const ImageRGBA& r, uint32_t lights,
                                          uint32_t samples, const std::string& what,
                                          const std::vector<uint8_t>* only = nullptr) {
    const double u = std::ldexp(1.0, -24);
    const double n = double(samples) * (lights + 1);
    double worstRatio = 0.0, worstRelative = 0.0;
    size_t worstPixel = 0;
    for (size_t i = 0; i < r.pixelCount(); ++i) {
        if (only && !(*only)[i]) continue;
        for (int c = 0; c < 3; ++c) {
            double x = d.rgba[i * 4 + c], y = r.rgba[i * 4 + c];
            double bound =
                (2.0 * (n - 1.0) + 6.0 + kEvaluationUlps) * u * std::max(std::abs(x), std::abs(y)) +
                1e-30;
            if (std::abs(x - y) / bound > worstRatio) worstPixel = i;
            worstRatio = std::max(worstRatio, std::abs(x - y) / bound);
            worstRelative = std::max(worstRelative, std::abs(x - y) / (std::abs(y) + 1e-4));
        }
    }
    EXPECT_LE(worstRatio, 1.0) << what
                               << ": deferred against the depth reference, worst |d - r| / bound = "
                               << worstRatio;
    std::printf("[ vs depth reference ] %s: worst difference = %.3g of the bound (%.3g relative) "
                "at %zu,%zu\n",
                what.c_str(), worstRatio, worstRelative, worstPixel % r.width,
                worstPixel / r.width);
    return worstRatio;
}

// (b): asserted below `bound` on a CPU device (lavapipe in CI), printed everywhere.
void checkReconstructionError(const GpuContext& ctx, double value, double bound,
                              const std::string& what) {
    std::printf("[ reconstruction ] %s: %.3g (lavapipe bound %.3g%s)\n", what.c_str(), value, bound,
                ctx.isCpuDevice() ? "" : ", not asserted on this device");
    if (ctx.isCpuDevice()) {
        EXPECT_LT(value, bound) << what << ": depth reference against the interpolated one";
    }
}

// Deferred and both references of one setting.
struct Split {
    RunResult deferred, fromDepth, interpolated;
};

Split renderSplit(GpuContext& ctx, SceneGpu& scene, const RenderSettings& settings) {
    Split p;
    p.deferred = runOrFail(ctx, scene, "deferred", settings);
    p.fromDepth = runOrFail(ctx, scene, "reference", withPosition(settings, "depth"));
    p.interpolated = runOrFail(ctx, scene, "reference", withPosition(settings, "interpolated"));
    return p;
}

// wide, 1x, the floor. (a) Deferred against the depth reference within the bound above.
// (b) The reconstruction error: 2.5e-4 relative per channel (floor 1e-4 absolute), the bound
// deferred against the interpolated reference had, measured on lavapipe, where that
// difference is the D32 reconstruction (~1e-6 relative in position) seen through the GGX lobe
// (before the split: worst 7.4e-5 at 1 light, 7.9e-5 at 4,096).
TEST(Deferred, WideMatchesReferenceOnTheFloor) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    for (uint32_t lights : {0u, 1u, 256u, 4096u}) {
        Scene scene = floorWithLights(lights);
        SceneGpu gpuScene(*ctx, scene);
        Split p = renderSplit(*ctx, gpuScene, small(1, "wide"));
        const std::string what = "floor " + std::to_string(lights) + " lights 1x";
        EXPECT_EQ(computeError(p.deferred.hdr, p.interpolated.hdr).nanInfCount, 0u) << what;
        expectWithinTheDepthReferenceBound(p.deferred.hdr, p.fromDepth.hdr, lights, 1, what);
        checkReconstructionError(*ctx, maxRelativeError(p.fromDepth.hdr, p.interpolated.hdr, 1e-4),
                                 2.5e-4, what);
    }
    expectNoValidationMessages(*ctx);
}

// wide, 1x, courtyard-small (textures, masked panels, blended cloth, emissive strips).
// (a) Deferred against the depth reference within the bound above on every pixel: the
// blended cloth is lit forward at its interpolated position by both (the depth reference
// moves only what a G-buffer holds), its culled list summed in fp32 against the reference's
// fp64, and the blend (src * a + dst * (1 - a), both >= 0) keeps a relative bound of its
// operands'. (b) The reconstruction error as a mean relative error of 1e-4 (the old bound,
// measured on lavapipe: 2e-6 before the split; the worst single pixel is bounded on the
// floor instead: a light that nearly touches a surface magnifies the position error, see
// SampleRateGBufferMatchesTheSupersampledReferenceAt4x).
TEST(Deferred, WideMatchesReferenceOnTheCourtyard) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    for (uint32_t lights : {0u, 1u, 256u, 4096u}) {
        Scene scene = courtyardWithLights(lights);
        SceneGpu gpuScene(*ctx, scene);
        Split p = renderSplit(*ctx, gpuScene, small(1, "wide"));
        const std::string what = "courtyard " + std::to_string(lights) + " lights 1x";
        EXPECT_EQ(computeError(p.deferred.hdr, p.interpolated.hdr).nanInfCount, 0u) << what;
        expectWithinTheDepthReferenceBound(p.deferred.hdr, p.fromDepth.hdr, lights, 1, what);
        checkReconstructionError(*ctx,
                                 computeError(p.fromDepth.hdr, p.interpolated.hdr).meanRelative,
                                 1e-4, what + " (mean)");
    }
    expectNoValidationMessages(*ctx);
}

// 4x MSAA, --msaa-shading sample: the material is evaluated at every sample, so every
// sample is lit from its own G-buffer values at its own position (reconstructed from its
// depth at the standard sample location), which is what the supersampled reference computes
// at the interpolated position and the depth reference at that very reconstructed position.
// (a) Deferred against the depth reference, the bound above with N = 4 (lights + 1).
// (b) The reconstruction error with the bounds of 1x: on the floor 2.5e-4 relative per
// channel (floor 1e-4 absolute); on the courtyard a mean relative error of 1e-4, because a
// light that nearly touches a surface turns the D32 reconstruction's ~1e-6 relative position
// error into (distance to the eye / distance to the light) times more: one pixel lit to ~400
// by such a light differed by 6e-4 relative at 1x and 8.8e-4 at 4x (4,096 lights, lavapipe,
// before the split), the same pixel and the same cause at both rates.
TEST(Deferred, SampleRateGBufferMatchesTheSupersampledReferenceAt4x) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    RenderSettings s = small(4, "wide");
    s.set("msaa-shading", "sample");
    for (uint32_t lights : {0u, 1u, 256u, 4096u}) {
        for (bool courtyard : {false, true}) {
            Scene scene = courtyard ? courtyardWithLights(lights) : floorWithLights(lights);
            SceneGpu gpuScene(*ctx, scene);
            Split p = renderSplit(*ctx, gpuScene, s);
            const std::string what = std::string(courtyard ? "courtyard " : "floor ") +
                                     std::to_string(lights) + " lights 4x sample-rate";
            EXPECT_EQ(computeError(p.deferred.hdr, p.interpolated.hdr).nanInfCount, 0u) << what;
            // (a) per sample, resolved: N = 4 (lights + 1).
            expectWithinTheDepthReferenceBound(p.deferred.hdr, p.fromDepth.hdr, lights, 4, what);
            // (b) as at 1x: the worst pixel on the floor, the mean on the courtyard.
            if (courtyard)
                checkReconstructionError(
                    *ctx, computeError(p.fromDepth.hdr, p.interpolated.hdr).meanRelative, 1e-4,
                    what + " (mean)");
            else
                checkReconstructionError(
                    *ctx, maxRelativeError(p.fromDepth.hdr, p.interpolated.hdr, 1e-4), 2.5e-4,
                    what);
        }
    }
    expectNoValidationMessages(*ctx);
}

// 4x MSAA, --msaa-shading pixel (Lauritzen 2010, the default) on the floor scene, whose
// materials and face normals are constant per triangle, so a per-pixel G-buffer value is
// exactly the value at any sample of that triangle:
//  - a pixel the edge mask leaves out is lit once at its centre (mean sample depth): it must
//    equal the depth reference with --reference-msaa center (every sample lit at the pixel
//    centre, at the depth there);
//  - an edge pixel is lit per sample at the sample's position: it must equal the
//    supersampled depth reference.
// (a) Both within the depth-reference bound above (N = 4 (lights + 1): the resolve). On the
// other pixels the two take the centre's depth in two ways (deferred: the mean of the four
// stored depths; the reference: its sample's depth moved along the primitive's slope), equal
// to about an ulp, which the GGX lobe magnifies: the closest to the bound of all these
// checks (lavapipe: 0.69 of it at 1 light).
// (b) The reconstruction error of the centre-shaded reference on the other pixels, 2.5e-4
// relative per channel as on the floor at 1x (the supersampled one's is bounded on the whole
// floor by SampleRateGBufferMatchesTheSupersampledReferenceAt4x: the same images). The
// difference between the two depth references on non-edge pixels is the cost of lighting
// once per pixel; it is printed, not bounded (a light close to a surface makes it as large
// as the light is bright).
TEST(Deferred, PixelRateGBufferLightsEdgesPerSampleAndTheRestAtTheCentre) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    for (uint32_t lights : {0u, 1u, 256u, 4096u}) {
        Scene scene = floorWithLights(lights);
        SceneGpu gpuScene(*ctx, scene);
        RenderSettings s = small(4, "wide");
        s.debug = true;
        RunResult deferred = runOrFail(*ctx, gpuScene, "deferred", s);
        RunResult samplesDepth = runOrFail(*ctx, gpuScene, "reference", withPosition(s, "depth"));
        s.set("reference-msaa", "center");
        RunResult centreDepth = runOrFail(*ctx, gpuScene, "reference", withPosition(s, "depth"));
        RunResult centre = runOrFail(*ctx, gpuScene, "reference", withPosition(s, "interpolated"));
        const ImageRGBA* edges = debugImageOf(deferred, "edge_mask");
        ASSERT_NE(edges, nullptr);
        const size_t pixels = deferred.hdr.pixelCount();
        std::vector<uint8_t> isEdge(pixels), isOther(pixels);
        double shadingRate = 0;
        for (size_t i = 0; i < pixels; ++i) {
            isEdge[i] = edges->rgba[i * 4] > 0.5f;
            isOther[i] = !isEdge[i];
            if (isEdge[i]) continue;
            for (int c = 0; c < 3; ++c) {
                double r = centreDepth.hdr.rgba[i * 4 + c], t = samplesDepth.hdr.rgba[i * 4 + c];
                shadingRate = std::max(shadingRate, std::abs(r - t) / (std::abs(t) + 1e-4));
            }
        }
        const size_t edgeCount = size_t(std::count(isEdge.begin(), isEdge.end(), uint8_t(1)));
        std::printf("[ 4x pixel-rate ] %u lights: %zu edge pixels, %zu others (centre against the "
                    "supersampled "
                    "reference: %.3g)\n",
                    lights, edgeCount, pixels - edgeCount, shadingRate);
        EXPECT_GT(edgeCount, 0u) << "the box's silhouette must be found";
        EXPECT_GT(pixels - edgeCount, edgeCount) << "most of the floor is one surface per pixel";
        const std::string what = std::to_string(lights) + " lights 4x pixel-rate, ";
        expectWithinTheDepthReferenceBound(deferred.hdr, samplesDepth.hdr, lights, 4,
                                           what + "edge pixels against the supersampled reference",
                                           &isEdge);
        expectWithinTheDepthReferenceBound(
            deferred.hdr, centreDepth.hdr, lights, 4,
            what + "other pixels against the centre-shaded reference", &isOther);
        checkReconstructionError(*ctx,
                                 maxRelativeError(centreDepth.hdr, centre.hdr, 1e-4, &isOther),
                                 2.5e-4, what + "other pixels, centre-shaded");
    }
    expectNoValidationMessages(*ctx);
}

// 4x, --msaa-shading pixel, the courtyard with its blended cloth: the hybrid forward pass
// shades a blended fragment once per pixel at its centre, as Forward+'s and multipass's
// blended draws do, and blends that value into every sample the primitive covers. On a pixel
// the edge mask leaves out (one opaque surface) deferred then computes what the depth
// reference with --reference-msaa center computes: the opaque surface lit once at the centre
// (PixelRateGBufferLightsEdgesPerSampleAndTheRestAtTheCentre), the cloth shaded at the
// centre with its interpolated position and the same per-sample coverage, blended per
// sample and resolved. (a) Within the depth-reference bound with N = 4 (lights + 1): a blend
// src * a + dst * (1 - a) of non-negative operands keeps their relative bound, so the bound
// of the opaque part carries over, as it does on the courtyard at 1x and at the sample rate.
// Before, the blended pass shaded every sample at its own position over an opaque surface lit
// once at the centre: 8.9e4 times the bound at 0 lights (0.105 relative), 2.2e3 times at 256
// (0.27 relative) on lavapipe; now 0 (bit-identical) and 0.10 of it. (b) The reconstruction
// error of the centre-shaded reference on those pixels (edge pixels set to 0 in both), as a
// mean relative error: the courtyard's 1e-4. (a) holds on the pixels whose samples lie on one
// triangle; (c) the others, held to deferred's registered model (the comment at (c) and
// docs/deferred.md say why: a device that snaps vertices before its depth planes).
// Masked materials made opaque: their coverage is a question of the G-buffer pass, not of this
// one (PixelRateGBufferKeepsPerSampleAlphaCoverage).
TEST(Deferred, PixelRateBlendedSurfacesAreShadedOnceAtTheCentre) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    for (uint32_t lights : {0u, 256u}) {
        Scene scene = courtyardWithLights(lights);
        for (Material& m : scene.materials)
            if (m.alphaMode == AlphaMode::Mask) m.alphaMode = AlphaMode::Opaque;
        SceneGpu gpuScene(*ctx, scene);
        RenderSettings s = small(4, "wide");
        s.set("msaa-shading", "pixel");
        s.debug = true;
        RunResult deferred = runOrFail(*ctx, gpuScene, "deferred", s);
        s.set("reference-msaa", "center");
        RunResult centreDepth = runOrFail(*ctx, gpuScene, "reference", withPosition(s, "depth"));
        RunResult centre = runOrFail(*ctx, gpuScene, "reference", withPosition(s, "interpolated"));
        const ImageRGBA* edges = debugImageOf(deferred, "edge_mask");
        ASSERT_NE(edges, nullptr);
        std::vector<uint8_t> isOther(deferred.hdr.pixelCount());
        ImageRGBA a = centreDepth.hdr, b = centre.hdr; // the other pixels only, for the mean
        for (size_t i = 0; i < isOther.size(); ++i) {
            isOther[i] = edges->rgba[i * 4] <= 0.5f;
            for (int c = 0; c < 4 && !isOther[i]; ++c)
                a.rgba[i * 4 + c] = b.rgba[i * 4 + c] = 0.0f;
        }
        const std::string what =
            "courtyard " + std::to_string(lights) + " lights 4x pixel-rate, other pixels";
        EXPECT_EQ(computeError(deferred.hdr, centre.hdr).nanInfCount, 0u) << what;
        // (c) Where the samples lie on more than one triangle (or a sample is within the
        // device's snapping distance of its triangle's edge), "at the centre" is two positions
        // on a device that snaps vertices before it sets up each triangle's depth plane (an
        // H200): the depth reference moves each sample's depth along its own triangle's plane
        // to the centre, deferred averages the samples' depths, and two triangles of one plane
        // have planes up to 2^-(bits + 1) pixels apart; next to a light, on a face seen edge-on,
        // that is 1e-3 of the radiance (pixel 63,27 here: four triangles of one face of the
        // colonnade, depth 6.5 % steeper per pixel; 11x this bound on the H200, 0.1x on
        // lavapipe, which sets up the plane from the unsnapped vertices). Those pixels are held
        // to deferred's registered model against the centre reference, whose per-pixel term is
        // that snapping distance times the light terms' gradient.
        const TrianglePixels triangles = findManyTrianglePixels(
            scene, s.width, s.height, 4,
            std::ldexp(1.0, -int(ctx->properties.limits.subPixelPrecisionBits)));
        std::vector<uint8_t> oneTriangle(isOther.size()), manyTriangles(isOther.size());
        size_t manyCount = 0;
        for (size_t i = 0; i < isOther.size(); ++i) {
            oneTriangle[i] = isOther[i] && !triangles.manyTriangles[i];
            manyTriangles[i] = isOther[i] && triangles.manyTriangles[i];
            manyCount += manyTriangles[i];
        }
        expectWithinTheDepthReferenceBound(
            deferred.hdr, centreDepth.hdr, lights, 4,
            what + " on one triangle, against the centre-shaded reference", &oneTriangle);
        const ErrorBound model = centreModelBound(*ctx, scene, "deferred", s, centre);
        ASSERT_TRUE(model.bounded) << model.why;
        const WorstRatio w = worstRatio(deferred.hdr, centre.hdr, model, &manyTriangles);
        std::printf("[ triangles ] %s on more than one triangle: %zu pixels, worst |d|/model %.3g "
                    "at %u,%u\n",
                    what.c_str(), manyCount, w.ratio, w.x, w.y);
        EXPECT_LE(w.ratio, 1.0) << what << " on more than one triangle: pixel " << w.x << "," << w.y
                                << ": " << w.got << " against " << w.ref;
        checkReconstructionError(*ctx, computeError(a, b).meanRelative, 1e-4,
                                 what + ", centre-shaded (mean)");
    }
    expectNoValidationMessages(*ctx);
}

// 4x, --msaa-shading pixel, on a scene whose only material is alpha-masked (round holes in a
// sphere and its floor, writeMaskedScene): which samples a masked surface covers is the alpha
// at each sample, in the centre reference (it alpha-tests every sample and shades at the
// centre) and in the other pipelines (their per-sample masked prepass), so deferred's
// per-pixel G-buffer must cover the same samples: it alpha-tests each sample's own location
// and writes gl_SampleMask (gbuffer.frag, TP_SAMPLE_COVERAGE). (a) The published depth is
// sample 0's, from the same triangles and vertex shader: equal to the centre reference's bit
// for bit on every pixel. (b) The pixels where the two cover different samples differ by a
// whole sample's share, beyond deferred's registered model (pixel rate: its shading-rate term
// included): none may. Before, the G-buffer took the centre's alpha for the whole pixel:
// (a) failed on the pixels along the holes' contours where sample 0 and the centre disagree.
TEST(Deferred, PixelRateGBufferKeepsPerSampleAlphaCoverage) {
    Result<Scene> loaded = loadMaskedScene(32, 5);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    Scene scene = std::move(*loaded);

    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    SceneGpu gpuScene(*ctx, scene);
    RenderSettings s = small(4, "wide");
    s.set("msaa-shading", "pixel");
    s.set("reference-msaa", "center");
    const RunResult deferred = runOrFail(*ctx, gpuScene, "deferred", s);
    const RunResult centre = runOrFail(*ctx, gpuScene, "reference", s);
    ASSERT_EQ(deferred.depth.r.size(), centre.depth.r.size());
    size_t depthDiffers = 0, covered = 0;
    for (size_t i = 0; i < centre.depth.r.size(); ++i) {
        depthDiffers += deferred.depth.r[i] != centre.depth.r[i];
        covered += centre.depth.r[i] != 0.0f; // reverse-Z: 0 is the far plane, nothing drawn
    }
    const ErrorReport e = computeError(deferred.hdr, centre.hdr);
    std::printf("[ 4x pixel-rate ] alpha-tested surfaces: %zu of %zu pixels' sample 0 covered in "
                "the centre reference, %zu with another depth in deferred; hdr rmse %.3g "
                "against the centre reference\n",
                covered, centre.depth.r.size(), depthDiffers, e.rmse);
    EXPECT_GT(covered, centre.depth.r.size() / 16) << "the masked surfaces are in view";
    EXPECT_EQ(depthDiffers, 0u) << "sample 0's coverage differs from the centre reference's";
    EXPECT_EQ(e.nanInfCount, 0u);
    expectNoValidationMessages(*ctx);
}

// compact, 1x: per pixel, base colour through 8-bit sRGB moves a channel by at most
// 2.4 * (0.5/255) / (s + 0.055) relative (1.2 % for the darkest channel here, 0.1 linear),
// roughness through 8 bits moves GGX D * Vis by at most 6 * (0.5/255) / r = 3.9 % at
// r = 0.3 (|dlnD/dlnr| <= 4, |dlnVis/dlnr| <= 2), and octahedral RG16_SNORM normals move by
// <= 6.5e-5 rad (CPU test). Sum of the worst cases: 5.1 %. Measured: 1.2 %.
TEST(Deferred, CompactWithinTheEncodingBound) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Pair p = renderBoth(*ctx, floorWithLights(1), small(1, "compact"));
    EXPECT_LT(maxRelativeError(p.deferred.hdr, p.reference.hdr, 1e-4), 0.051) << describe(p.error);
    // The courtyard's textured roughness goes below 0.3, where no per-pixel bound of this
    // size holds; its mean stays under the same figure (measured 0.29 %).
    Pair c = renderBoth(*ctx, courtyardWithLights(64), small(1, "compact"));
    EXPECT_EQ(c.error.nanInfCount, 0u);
    EXPECT_LT(c.error.meanRelative, 0.051) << describe(c.error);
    expectNoValidationMessages(*ctx);
}

RenderSettings withLighting(RenderSettings s, const char* lighting) {
    s.set("deferred-lighting", lighting);
    return s;
}

TEST(Deferred, VolumesAgreeWithTiled) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    // 5 = 4x with the sample-rate G-buffer (every pixel lit per sample in both modes).
    for (uint32_t mode : {1u, 4u, 5u})
        for (uint32_t lights : {0u, 1u, 256u}) {
            Scene scene = floorWithLights(lights);
            SceneGpu gpuScene(*ctx, scene);
            const uint32_t msaa = std::min(mode, 4u);
            RenderSettings s = small(msaa, "wide");
            if (mode == 5u) s.set("msaa-shading", "sample");
            RunResult tiled = runOrFail(*ctx, gpuScene, "deferred", withLighting(s, "tiled"));
            RunResult volumes = runOrFail(*ctx, gpuScene, "deferred", withLighting(s, "volumes"));
            std::string what = "floor " + std::to_string(lights) + " lights " +
                               std::to_string(msaa) + "x " + (mode == 5u ? "sample" : "pixel");
            expectAgreeWithinSummationBound(tiled.hdr, volumes.hdr, lights, msaa, what);
        }
    // The courtyard has blended cloth: under MSAA both modes light hdr_msaa per sample and the
    // hybrid forward pass blends into it (the same blend of the same values, so the same bound).
    Scene courtyard = courtyardWithLights(64);
    SceneGpu courtyardGpu(*ctx, courtyard);
    for (const char* rate : {"pixel", "sample"}) {
        RenderSettings s = small(4, "wide");
        s.set("msaa-shading", rate);
        RunResult tiled = runOrFail(*ctx, courtyardGpu, "deferred", withLighting(s, "tiled"));
        RunResult volumes = runOrFail(*ctx, courtyardGpu, "deferred", withLighting(s, "volumes"));
        expectAgreeWithinSummationBound(tiled.hdr, volumes.hdr, 64, 4,
                                        std::string("courtyard 64 lights 4x ") + rate);
    }
    expectNoValidationMessages(*ctx);
}

double counter(const RunResult& run, const std::string& name) {
    for (const auto& [n, v] : run.stats.counters)
        if (n == name) return v;
    return -1.0;
}

// Binned culling (--light-cull binned, the default) tests each tile's candidates only; it
// must find exactly what testing every light finds: the same number of lights in every
// tile's opaque and transparent lists (summed and fullest), the same image up to the order
// of the fp32 sum (the lists hold the same lights in ascending order, but the batches of the
// tiled pass split candidates, not lights: a tile over one batch adds its lights in other
// groups), with fewer tests.
TEST(Deferred, BinnedCullingFindsWhatEveryLightFinds) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardWithLights(256);
    SceneGpu gpuScene(*ctx, scene);
    for (uint32_t msaa : {1u, 4u}) {
        RenderSettings s = small(msaa, "wide");
        s.set("light-cull", "all");
        RunResult all = runOrFail(*ctx, gpuScene, "deferred", s);
        s.set("light-cull", "binned");
        RunResult binned = runOrFail(*ctx, gpuScene, "deferred", s);
        for (const char* c :
             {"lights_per_tile_mean", "lights_per_tile_max", "transparent_lights_stored"}) {
            EXPECT_EQ(counter(binned, c), counter(all, c)) << c << " " << msaa << "x";
            EXPECT_GT(counter(binned, c), 0.0) << c;
        }
        EXPECT_EQ(counter(binned, "transparent_lights_dropped"), 0.0);
        EXPECT_LT(counter(binned, "light_candidates"), counter(all, "light_candidates"));
        std::printf("[ deferred ] binned culling %ux: %.0f light-tile tests against %.0f\n", msaa,
                    counter(binned, "light_candidates"), counter(all, "light_candidates"));
        expectAgreeWithinSummationBound(binned.hdr, all.hdr, 256, msaa,
                                        "binned vs all " + std::to_string(msaa) + "x");
    }
    expectNoValidationMessages(*ctx);
}

// Clustered (--light-assign clustered): each sample takes only the lights of its depth
// slice (include/light_assign.glsl: laSliceOf over the tile's opaque range). Culling stays
// conservative, so the bound of the tiled runs holds: deferred against the depth reference
// within expectWithinTheDepthReferenceBound, on the floor and on the courtyard (the
// reconstruction error of the same reference images is WideMatchesReferenceOnTheFloor's and
// WideMatchesReferenceOnTheCourtyard's); and it agrees with tiled within the summation bound
// (both sum the same non-zero terms, in the shared list's order).
TEST(Deferred, ClusteredWithinTheTiledBounds) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    // The references read no light-assignment knob: rendered once per scene, for every slice
    // count; their reconstruction error is checked on these very images by
    // WideMatchesReferenceOnTheFloor and WideMatchesReferenceOnTheCourtyard.
    for (uint32_t lights : {256u, 4096u}) {
        Scene scene = floorWithLights(lights);
        SceneGpu gpuScene(*ctx, scene);
        RenderSettings s = small(1, "wide");
        RunResult fromDepth = runOrFail(*ctx, gpuScene, "reference", withPosition(s, "depth"));
        s.set("light-assign", "clustered");
        for (uint32_t slices : {4u, 64u}) {
            s.set("slices", slices);
            RunResult clustered = runOrFail(*ctx, gpuScene, "deferred", s);
            const std::string what = "floor " + std::to_string(lights) + " lights, " +
                                     std::to_string(slices) + " slices";
            EXPECT_EQ(computeError(clustered.hdr, fromDepth.hdr).nanInfCount, 0u) << what;
            expectWithinTheDepthReferenceBound(clustered.hdr, fromDepth.hdr, lights, 1, what);
        }
    }
    Scene courtyard = courtyardWithLights(256);
    SceneGpu gpuScene(*ctx, courtyard);
    RunResult fromDepth =
        runOrFail(*ctx, gpuScene, "reference", withPosition(small(1, "wide"), "depth"));
    for (uint32_t slices : {4u, 64u}) {
        for (uint32_t msaa : {1u, 4u}) {
            RenderSettings s = small(msaa, "wide");
            if (msaa > 1) s.set("msaa-shading", "sample");
            RunResult tiled = runOrFail(*ctx, gpuScene, "deferred", s);
            s.set("light-assign", "clustered");
            s.set("slices", slices);
            RunResult clustered = runOrFail(*ctx, gpuScene, "deferred", s);
            expectAgreeWithinSummationBound(clustered.hdr, tiled.hdr, 256, msaa,
                                            "courtyard clustered vs tiled, " +
                                                std::to_string(slices) + " slices");
            if (msaa == 1)
                expectWithinTheDepthReferenceBound(clustered.hdr, fromDepth.hdr, 256, 1,
                                                   "courtyard 256 lights, " +
                                                       std::to_string(slices) + " slices");
        }
    }
    expectNoValidationMessages(*ctx);
}

// More lights in every tile than the 4,096-light shared list, each reaching the whole view.
// lavapipe ends a shader invocation after 65,535 loop iterations in total; an invocation
// shades (tile / 8)^2 pixels, so before the lights came in batches (tiledLightBatch) tile 32
// at 1x (16 pixels x 6,000 lights per invocation) and tile 16 at 4x (4 pixels x 4 edge
// samples) left later pixels unshaded or half shaded: deterministic, whole 8x8 blocks wrong.
// Volumes lighting (one draw per light, no long loop) is the comparison, within the
// summation bound above: the batches store partial sums in the fp32 hdr, exactly.
TEST(Deferred, TiledShadesEveryLightBeyondTheSharedListAndTheLoopLimit) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const uint32_t lights = 6000;
    Scene scene = makeFloorScene({});
    LightGenOptions o;
    o.count = lights;
    o.seed = 5;
    o.radiusMin = o.radiusMax = 2.0f * glm::length(scene.bounds.max - scene.bounds.min);
    scene.lights = generateLights(scene.bounds, o);
    SceneGpu gpuScene(*ctx, scene);
    for (auto [tile, msaa] : {std::pair{32u, 1u}, std::pair{16u, 4u}}) {
        RenderSettings s = small(msaa, "wide");
        s.width = s.height = 32;
        s.set("tile", tile);
        RunResult tiled = runOrFail(*ctx, gpuScene, "deferred", withLighting(s, "tiled"));
        RunResult volumes = runOrFail(*ctx, gpuScene, "deferred", withLighting(s, "volumes"));
        std::string what = "floor " + std::to_string(lights) + " lights, tile " +
                           std::to_string(tile) + ", " + std::to_string(msaa) + "x";
        expectAgreeWithinSummationBound(tiled.hdr, volumes.hdr, lights, msaa, what);
        EXPECT_EQ(counter(tiled, "lights_per_tile_max"), double(lights)) << what;
        EXPECT_EQ(counter(tiled, "tiles_over_shared_capacity"), double((32 / tile) * (32 / tile)))
            << what;
    }
    expectNoValidationMessages(*ctx);
}

// Every volume kind and the awkward cases: spots (cone mesh, and a 80-degree one drawn
// with the sphere), directional lights (full-screen triangle), a point and a spot light
// around the camera (camera inside the volume: only back faces are drawn, so nothing is
// lost), and a finite far plane that cuts volumes (flattened onto depth 0). Same bound as
// above; at 1x volumes also stays within the bounds of WideMatchesReferenceOnTheFloor: (a)
// against the depth reference, (b) the reconstruction error within 2.5e-4.
Scene floorWithEveryLightKind(float zfar) {
    Scene s = makeFloorScene({});
    LightGenOptions o;
    o.count = 48;
    o.seed = 5;
    o.spotWeight = 1.0f;
    o.directionalWeight = 0.1f;
    s.lights = generateLights(s.bounds, o);
    Light around;
    around.position = s.camera.position + glm::vec3(0.1f, -0.1f, 0.0f);
    around.range = 2.0f * glm::length(s.camera.position - s.camera.target);
    around.intensity = 2.0f;
    s.lights.push_back(around);
    Light spot = around;
    spot.type = LightType::Spot;
    spot.direction = glm::normalize(s.camera.target - s.camera.position);
    spot.outerConeAngle = 0.4f;
    spot.innerConeAngle = 0.2f;
    s.lights.push_back(spot);
    spot.outerConeAngle = 1.4f; // wider than 60 degrees: the sphere bounds it
    spot.position += glm::vec3(0.5f, 0.5f, 0.0f);
    s.lights.push_back(spot);
    s.camera.zfar = zfar;
    return s;
}

TEST(Deferred, VolumesHandleEveryLightKindACameraInsideAndAFarPlane) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    for (float zfar : {0.0f, 9.0f}) {
        Scene scene = floorWithEveryLightKind(zfar);
        SceneGpu gpuScene(*ctx, scene);
        uint32_t n = uint32_t(scene.lights.size());
        for (uint32_t msaa : {1u, 4u}) {
            RunResult tiled =
                runOrFail(*ctx, gpuScene, "deferred", withLighting(small(msaa, "wide"), "tiled"));
            RunResult volumes =
                runOrFail(*ctx, gpuScene, "deferred", withLighting(small(msaa, "wide"), "volumes"));
            std::string what =
                "every kind, zfar " + std::to_string(zfar) + ", " + std::to_string(msaa) + "x";
            expectAgreeWithinSummationBound(tiled.hdr, volumes.hdr, n, msaa, what);
            if (msaa > 1) continue;
            RunResult fromDepth =
                runOrFail(*ctx, gpuScene, "reference", withPosition(small(1, "wide"), "depth"));
            RunResult reference = runOrFail(*ctx, gpuScene, "reference", small(1, "wide"));
            expectWithinTheDepthReferenceBound(volumes.hdr, fromDepth.hdr, n, 1, what);
            checkReconstructionError(*ctx, maxRelativeError(fromDepth.hdr, reference.hdr, 1e-4),
                                     2.5e-4, what);
        }
    }
    expectNoValidationMessages(*ctx);
}

uint64_t gbufferBytes(const RunResult& run, bool msaa) {
    uint64_t bytes = 0;
    for (const LedgerEntry& e : run.memory)
        if (e.tag.name.rfind("gbuffer_", 0) == 0 || (!msaa && e.tag.name == "depth"))
            bytes += e.requestedBytes;
    return bytes;
}

bool hasEntry(const RunResult& run, const std::string& name) {
    for (const LedgerEntry& e : run.memory)
        if (e.tag.name == name) return true;
    return false;
}

// compact = RGBA8 + RG16 + RG8 + D32 = 14 bytes per sample (+4 with a B10G11R11 emissive
// target or +8 with RGBA16F); wide = 16 + 16 + 8 + 4 = 44 (+16).
TEST(Deferred, LedgerHoldsTheLayoutsBytesAndNoUnneededTargets) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene floor = floorWithLights(1);
    SceneGpu floorGpu(*ctx, floor);
    for (uint32_t msaa : {1u, 4u})
        for (auto [layout, bytes] : {std::pair{"compact", 14u}, std::pair{"wide", 44u}}) {
            RunResult r = runOrFail(*ctx, floorGpu, "deferred", small(msaa, layout));
            EXPECT_EQ(gbufferBytes(r, msaa > 1), uint64_t(96) * 64 * msaa * bytes)
                << layout << " " << msaa;
            EXPECT_FALSE(hasEntry(r, "gbuffer_emissive"));
            EXPECT_FALSE(hasEntry(r, "transparent_lists"));
            EXPECT_EQ(hasEntry(r, "gbuffer_depth_msaa"), msaa > 1);
        }
    Scene yard = courtyardWithLights(4);
    SceneGpu yardGpu(*ctx, yard);
    RunResult r = runOrFail(*ctx, yardGpu, "deferred", small(1, "compact"));
    EXPECT_TRUE(hasEntry(r, "gbuffer_emissive"));
    EXPECT_TRUE(hasEntry(r, "transparent_lists"));
    uint64_t perSample = gbufferBytes(r, false) / (96 * 64);
    EXPECT_TRUE(perSample == 18 || perSample == 22) << perSample;
    expectNoValidationMessages(*ctx);
}

uint64_t entryBytes(const RunResult& run, const std::string& name) {
    for (const LedgerEntry& e : run.memory)
        if (e.tag.name == name) return e.requestedBytes;
    return 0;
}

// On a CPU device the lights and the materials are read from uniform-buffer copies where they
// fit (core/passes/lights_ubo.h, materials_ubo.h: lavapipe's storage-buffer loads branch per
// lane); the ledger shows which: the whole block when read, a one-element stand-in otherwise.
// Past 1,024 lights the shaders read the scene's buffer (the image is the same either way:
// the fingerprints and the reference tests at 4,096 lights).
TEST(Deferred, ReadsTheLightsAndMaterialsFromUniformCopiesOnACpuDevice) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    if (!ctx->isCpuDevice()) GTEST_SKIP() << "the copies are read on a CPU device only";
    for (uint32_t lights : {4u, 1025u}) {
        Scene yard = courtyardWithLights(lights);
        SceneGpu yardGpu(*ctx, yard);
        RunResult r = runOrFail(*ctx, yardGpu, "deferred", small(1, "compact"));
        const uint64_t lightBytes = lights <= TP_LIGHTS_UBO_CAPACITY
                                        ? TP_LIGHTS_UBO_CAPACITY * sizeof(gpu::LightGpu)
                                        : sizeof(gpu::LightGpu);
        EXPECT_EQ(entryBytes(r, "lights_ubo"), lightBytes) << lights;
        EXPECT_EQ(entryBytes(r, "materials_ubo"), TP_MATERIALS_UBO_CAPACITY * sizeof(gpu::MaterialGpu))
            << lights;
        EXPECT_EQ(entryBytes(r, "transparent_forward_materials_ubo"),
                  TP_MATERIALS_UBO_CAPACITY * sizeof(gpu::MaterialGpu))
            << lights;
    }
    expectNoValidationMessages(*ctx);
}

// The transparent lists use light assignment's compact layout: one 16-byte header per tile,
// then runs sized by the conservative bound (the same bound as Forward+'s compact lists, so
// the same slots per list when no light is directional), far below tiles x lights, and no
// list drops a light. Volumes lighting builds the same lists in its lists-only pass.
TEST(Deferred, TransparentListsAreCompactAndDropNothing) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const uint32_t lights = 256;
    Scene yard = courtyardWithLights(lights);
    SceneGpu yardGpu(*ctx, yard);
    RenderSettings s = small(1, "compact");
    const uint64_t tiles = (96 / 16) * (64 / 16);
    RunResult fp = runOrFail(*ctx, yardGpu, "forwardplus", s);
    for (const char* lighting : {"tiled", "volumes"}) {
        // --light-cull all: index lists in the compact layout.
        RenderSettings all = withLighting(s, lighting);
        all.set("light-cull", "all");
        RunResult r = runOrFail(*ctx, yardGpu, "deferred", all);
        const double slots = counter(r, "transparent_list_slots");
        EXPECT_EQ(entryBytes(r, "transparent_lists"), tiles * 16 + uint64_t(slots) * 4) << lighting;
        EXPECT_EQ(slots, counter(fp, "light_list_slots") / 2) << lighting;
        EXPECT_LT(slots, double(tiles * lights)) << lighting;
        EXPECT_GT(counter(r, "transparent_lights_stored"), 0.0) << lighting;
        EXPECT_EQ(counter(r, "transparent_lights_dropped"), 0.0) << lighting;
        // Binned (the default): the same index lists (BinnedTransparentListsAreTheListsOf
        // EveryLight), each run sized from the tiled pass's candidates (the same conservative
        // bound: the same slots). The blended pass adds the ambient term after the lights
        // there (blended_forward.frag: kAmbientLast), so the images agree within the
        // summation bound.
        RunResult b = runOrFail(*ctx, yardGpu, "deferred", withLighting(s, lighting));
        const double binnedSlots = counter(b, "transparent_list_slots");
        EXPECT_EQ(binnedSlots, slots) << lighting;
        EXPECT_EQ(entryBytes(b, "transparent_lists"), tiles * 16 + uint64_t(binnedSlots) * 4)
            << lighting;
        EXPECT_EQ(counter(b, "transparent_lights_stored"), counter(r, "transparent_lights_stored"))
            << lighting;
        EXPECT_EQ(counter(b, "transparent_lights_dropped"), 0.0) << lighting;
        expectAgreeWithinSummationBound(b.hdr, r.hdr, lights, 1,
                                        std::string("binned vs all, ") + lighting);
    }
    expectNoValidationMessages(*ctx);
}

// --light-assign clustered lights blended surfaces from their own cluster: the tiled pass
// writes per-slice bitmask rows over each tile's transparent list (front slices from the
// near plane to the nearest opaque depth, range slices over the opaque range) and the
// blended pass walks its slice's row. The courtyard has blended cloth: clustered agrees with
// tiled within the summation bound on every pixel (the same lights, one sum order), and with
// the depth reference within its bound per pixel (WideMatchesReferenceOnTheCourtyard, which
// also checks the reconstruction error of these very reference images: the references read
// no light-assignment knob). The rows are in the ledger, sized as deferred_shared.h says;
// tiled has none.
TEST(Deferred, ClusteredBlendedSurfacesMatchTheReferenceOnTheCourtyard) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const uint64_t tiles = (96 / 16) * (64 / 16);
    for (uint32_t lights : {256u, 4096u}) {
        Scene yard = courtyardWithLights(lights);
        SceneGpu yardGpu(*ctx, yard);
        RenderSettings s = small(1, "wide");
        RunResult tiled = runOrFail(*ctx, yardGpu, "deferred", s);
        EXPECT_FALSE(hasEntry(tiled, "transparent_cluster_masks"));
        s.set("light-assign", "clustered");
        s.set("slices", 16);
        RunResult clustered = runOrFail(*ctx, yardGpu, "deferred", s);
        // Rows over the index lists (binned too): ceil(count / 32) words a row, from
        // tlClusterRowsBase, so floor(slots / 32) + tiles words a slice.
        const uint64_t slots = uint64_t(counter(clustered, "transparent_list_slots"));
        EXPECT_EQ(entryBytes(clustered, "transparent_cluster_masks"),
                  4 * (2 * tiles + 16 * (slots / 32 + tiles)));
        expectAgreeWithinSummationBound(clustered.hdr, tiled.hdr, lights, 1,
                                        "courtyard clustered vs tiled, " + std::to_string(lights) +
                                            " lights");
        RunResult fromDepth = runOrFail(*ctx, yardGpu, "reference", withPosition(s, "depth"));
        const std::string what = "courtyard clustered " + std::to_string(lights) + " lights";
        EXPECT_EQ(computeError(clustered.hdr, fromDepth.hdr).nanInfCount, 0u) << what;
        expectWithinTheDepthReferenceBound(clustered.hdr, fromDepth.hdr, lights, 1, what);
    }
    expectNoValidationMessages(*ctx);
}

// A blended wall far behind the floor, seen over the sky, lit by a light beside it: the tiles
// where the floor's far edge meets the sky hold floor pixels (their farthest opaque depth is
// the floor's) and wall pixels 15 m further back. The transparent range must be unbounded
// there (light assignment's laTransparentFarDepth: any sample without geometry), or the
// wall's light is culled from those tiles and two rows of wall pixels lose it. Bound as on
// the floor (WideMatchesReferenceOnTheFloor): 2.5e-4 relative per channel, floor 1e-4.
TEST(Deferred, BlendedSurfaceOverTheSkyKeepsLightsBeyondTheOpaqueDepth) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Light light;
    light.position = {0.0f, -6.5f,
                      -19.0f}; // lights the wall just above the floor's far edge on screen
    light.range = 4.0f;
    light.intensity = 50.0f;
    Scene scene = makeFloorScene({light});
    Material glass;
    glass.name = "glass";
    glass.baseColorFactor = glm::vec4(0.6f, 0.7f, 0.9f, 0.5f);
    glass.metallicFactor = 0.0f;
    glass.roughnessFactor = 0.8f;
    glass.alphaMode = AlphaMode::Blend;
    scene.materials.push_back(glass);
    Mesh wall;
    wall.name = "wall";
    wall.material = uint32_t(scene.materials.size() - 1);
    addQuad(wall, {-20.0f, -12.0f, -20.0f}, {40.0f, 0.0f, 0.0f}, {0.0f, 30.0f, 0.0f}); // faces +z
    scene.meshes.push_back(wall);
    scene.computeBounds();
    // Tiled: the transparent list; clustered: the wall's cluster (the last slice over the sky).
    for (const char* assign : {"tiled", "clustered"}) {
        RenderSettings settings = small(1, "wide");
        settings.set("light-assign", assign);
        Pair p = renderBoth(*ctx, scene, settings);
        EXPECT_EQ(p.error.nanInfCount, 0u);
        EXPECT_LT(maxRelativeError(p.deferred.hdr, p.reference.hdr, 1e-4), 2.5e-4)
            << assign << ": " << describe(p.error);
    }
    expectNoValidationMessages(*ctx);
}

// One frame of `pipeline`: the exported buffer `name` (and, when asked, `tile_stats`).
std::vector<uint8_t> exportedBuffer(GpuContext& ctx, SceneGpu& scene, const char* pipeline,
                                    const RenderSettings& settings, const char* name,
                                    std::vector<uint8_t>* tileStats = nullptr) {
    std::vector<std::string> names{name};
    if (tileStats) names.push_back("tile_stats");
    std::vector<std::vector<uint8_t>> got = exportedBuffers(ctx, scene, pipeline, settings, names);
    if (tileStats) *tileStats = got.at(1);
    return got.at(0);
}

// The transparent lists are culled against each tile's blended depth bounds
// (core/passes/blended_bounds.h): a tile with no blended fragment has an empty list
// (tile_stats' transparent column: what its test found), tiled and clustered, 1x and 4x.
// Forward+ records the same bounds from its prepass depth (the same vertex shader, depth
// test and fragments, at the same rate: per pixel or per sample under MSAA), bit for bit, and
// so does the visibility buffer (in its blended lists' pass where they share the fragments).
TEST(Deferred, TransparentListsAreEmptyWhereNoBlendedFragmentIs) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene yard = courtyardWithLights(256);
    SceneGpu yardGpu(*ctx, yard);
    const uint32_t tiles = (96 / 16) * (64 / 16);
    for (uint32_t msaa : {1u, 4u})
        for (const char* assign : {"tiled", "clustered"}) {
            RenderSettings s = small(msaa, "compact");
            s.set("light-assign", assign);
            std::vector<uint8_t> statBytes;
            std::vector<uint8_t> bytes =
                exportedBuffer(*ctx, yardGpu, "deferred", s, "blended_bounds", &statBytes);
            std::vector<la::TileBlendedBounds> b = la::unpackBlendedBounds(bytes, tiles);
            ASSERT_EQ(statBytes.size(), size_t(tiles) * 16);
            std::vector<uint32_t> stats(tiles * 4);
            std::memcpy(stats.data(), statBytes.data(), statBytes.size());
            uint32_t empty = 0, blended = 0;
            for (uint32_t t = 0; t < tiles; ++t) {
                if (b[t].any) {
                    ++blended;
                    continue;
                }
                ++empty;
                EXPECT_EQ(stats[t * 4 + 1], 0u) << assign << " " << msaa << "x tile " << t;
            }
            EXPECT_GT(empty, 0u) << assign << " " << msaa << "x";
            EXPECT_GT(blended, 0u) << assign << " " << msaa << "x";
            // Both shade blended fragments at the rate --msaa-shading gives (pixel: at the centre).
            for (const char* rate : {"pixel", "sample"}) {
                s.set("msaa-shading", rate);
                const std::vector<uint8_t> ours =
                    exportedBuffer(*ctx, yardGpu, "deferred", s, "blended_bounds");
                EXPECT_EQ(exportedBuffer(*ctx, yardGpu, "forwardplus", s, "blended_bounds"), ours)
                    << assign << " " << msaa << "x " << rate;
                // The visibility buffer's blended lists record them in their own draw where
                // they run per pixel (1x, pixel rate), its bounds pass otherwise.
                EXPECT_EQ(exportedBuffer(*ctx, yardGpu, "visbuffer", s, "blended_bounds"), ours)
                    << assign << " " << msaa << "x " << rate;
                if (msaa == 1) break; // the rate changes nothing at 1x
            }
        }
    expectNoValidationMessages(*ctx);
}

// The transparent index lists (--light-cull all) hold each tile's lights in ascending order,
// as the opaque lists do (compactList): the blended pass sums a list in its order, so an order
// the GPU picks reaches the last bits of blended pixels. They were an atomic append, whose
// order changed from run to run on a GPU (Determinism.* checks the images there). Lavapipe
// runs a group's invocations in one fixed order, so its images repeated anyway, but not in
// ascending order: this failed on it before (lights appended 8 lanes at a time, 64 apart).
// Tiled and volumes (its lists-only pass), 1x and 4x; 4,500 lights take two chunks of the
// shared bitmask (cullTransparentIndices), and a list must hold lights of both.
TEST(Deferred, TransparentIndexListsHoldTheirLightsInAscendingOrder) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    struct Case {
        uint32_t lights, msaa;
        const char* lighting;
    };
    const uint32_t tiles = (96 / 16) * (64 / 16);
    for (Case k : {Case{256, 1, "tiled"}, Case{256, 4, "tiled"}, Case{256, 4, "volumes"},
                   Case{4500, 1, "tiled"}}) {
        Scene yard = courtyardWithLights(k.lights);
        SceneGpu yardGpu(*ctx, yard);
        RenderSettings s = withLighting(small(k.msaa, "compact"), k.lighting);
        s.set("light-cull", "all");
        const std::string what =
            std::to_string(k.lights) + " lights " + std::to_string(k.msaa) + "x " + k.lighting;
        std::vector<uint8_t> bytes =
            exportedBuffer(*ctx, yardGpu, "deferred", s, "transparent_lists");
        std::vector<uint32_t> words(bytes.size() / 4);
        std::memcpy(words.data(), bytes.data(), words.size() * 4);
        ASSERT_GE(words.size(), size_t(tiles) * TP_LA_HEADER_WORDS) << what;
        size_t longest = 0, unordered = 0;
        bool bothChunks = false;
        for (uint32_t t = 0; t < tiles; ++t) {
            const uint32_t* h = &words[t * TP_LA_HEADER_WORDS];
            const uint32_t count = h[0], start = h[1];
            EXPECT_EQ(h[2], 0u) << what << " tile " << t << ": dropped";
            ASSERT_LE(size_t(start) + count, words.size()) << what << " tile " << t;
            for (uint32_t i = 0; i < count; ++i)
                EXPECT_LT(words[start + i], k.lights) << what << " tile " << t;
            for (uint32_t i = 1; i < count; ++i)
                unordered += words[start + i - 1] >= words[start + i];
            longest = std::max(longest, size_t(count));
            bothChunks = bothChunks ||
                         (count > 0 && words[start] < 4096 && words[start + count - 1] >= 4096);
        }
        EXPECT_EQ(unordered, 0u) << what << ": neighbours out of ascending order";
        EXPECT_GT(longest, 1u) << what << ": no list to order";
        EXPECT_TRUE(bothChunks || k.lights <= 4096)
            << what << ": no list with lights of both chunks";
        std::printf("[ transparent lists ] %s: longest %zu, %zu pairs out of order\n", what.c_str(),
                    longest, unordered);
    }
    expectNoValidationMessages(*ctx);
}

// Each tile's transparent list (its header's count, then its run), from the exported buffer.
std::vector<std::vector<uint32_t>> transparentListsOf(const std::vector<uint8_t>& bytes,
                                                      uint32_t tiles, const std::string& what) {
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), words.size() * 4);
    std::vector<std::vector<uint32_t>> lists(tiles);
    if (words.size() < size_t(tiles) * TP_LA_HEADER_WORDS) {
        ADD_FAILURE() << what << ": no headers";
        return lists;
    }
    for (uint32_t t = 0; t < tiles; ++t) {
        gpu::LaListHeader h;
        std::memcpy(&h, &words[t * TP_LA_HEADER_WORDS], sizeof h);
        const uint32_t count = h.count, start = h.start;
        if (size_t(start) + count > words.size()) {
            ADD_FAILURE() << what << " tile " << t << ": run past the buffer";
            continue;
        }
        lists[t].assign(words.begin() + start, words.begin() + start + count);
    }
    return lists;
}

// Under --light-cull binned the transparent lists are light indices too (the blended pass
// reads them as Forward+ reads its lists; they were bitmasks over the candidates), culled
// from each tile's candidates in candidate order. With no directional light that order is
// ascending light order, so they must be --light-cull all's lists, light for light, whether
// the candidates are binned on the CPU or on the GPU (which also lays the runs out itself:
// GpuBinning::publishWords, a word per candidate). Tiled, volumes (its lists-only pass) and
// clustered, 1x and 4x; 4,500 lights for long candidate runs.
TEST(Deferred, BinnedTransparentListsAreTheListsOfEveryLight) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    struct Case {
        uint32_t lights, msaa;
        const char* lighting;
        bool clustered;
    };
    const uint32_t tiles = (96 / 16) * (64 / 16);
    for (Case k : {Case{256, 1, "tiled", false}, Case{256, 4, "tiled", false},
                   Case{256, 4, "volumes", false}, Case{256, 1, "tiled", true},
                   Case{4500, 1, "tiled", false}}) {
        Scene yard = courtyardWithLights(k.lights);
        SceneGpu yardGpu(*ctx, yard);
        RenderSettings s = withLighting(small(k.msaa, "compact"), k.lighting);
        if (k.clustered) {
            s.set("light-assign", "clustered");
            s.set("slices", 16);
        }
        const std::string what = std::to_string(k.lights) + " lights " + std::to_string(k.msaa) +
                                 "x " + k.lighting + (k.clustered ? " clustered" : "");
        s.set("light-cull", "all");
        const std::vector<std::vector<uint32_t>> all = transparentListsOf(
            exportedBuffer(*ctx, yardGpu, "deferred", s, "transparent_lists"), tiles, what);
        size_t stored = 0;
        for (const std::vector<uint32_t>& l : all) stored += l.size();
        EXPECT_GT(stored, 0u) << what << ": no list to compare";
        s.set("light-cull", "binned");
        for (const char* bin : {"cpu", "gpu"}) {
            s.set("light-bin", bin);
            const std::vector<std::vector<uint32_t>> binned = transparentListsOf(
                exportedBuffer(*ctx, yardGpu, "deferred", s, "transparent_lists"), tiles, what);
            for (uint32_t t = 0; t < tiles; ++t)
                EXPECT_EQ(binned[t], all[t]) << what << ", binned on the " << bin << ", tile " << t;
        }
    }
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
