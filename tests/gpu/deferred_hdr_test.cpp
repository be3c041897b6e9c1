// Deferred's --hdr fp16 (hdr and hdr_msaa in RGBA16F, Forward+'s format) on the default
// device, validation on. The bound is the error model's "fp16 colour storage" term
// (deferred/error_model.cpp, through addFp16StorageTerm: the function Forward+'s model uses;
// one rounding per store a pixel's sum goes through) plus one rounding per blended layer,
// as Forward+'s tests count them (4 on courtyard-small). docs/deferred.md, "Storage precision".
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/gpu/ledger.h"
#include "core/image/metrics.h"
#include "core/renderer/error_model.h"
#include "core/scene/lights.h"
#include "core/scene/procedural.h"
#include "gpu_test_util.h"

namespace tp::test {
namespace {

constexpr uint32_t kCourtyardBlendLayers =
    4; // as forwardplus_test.cpp counts them on courtyard-small

Scene courtyard(uint32_t count) {
    return courtyardSmallWithLights(count, 11);
}

RenderSettings settingsFor(uint32_t msaa, const char* hdr, const char* lighting) {
    RenderSettings s;
    s.width = 96;
    s.height = 64;
    s.msaa = msaa;
    s.set("gbuffer", "wide");
    s.set("hdr", hdr);
    s.set("deferred-lighting", lighting);
    return s;
}

// The storage bound of an fp16 run: the model's term plus the blended layers' roundings.
BoundTerm storageBound(const Scene& scene, const RenderSettings& settings, uint32_t layers) {
    Result<const RendererEntry*> entry = findRenderer("deferred");
    EXPECT_TRUE(entry.ok());
    RenderSettings resolved = settings;
    EXPECT_TRUE(resolveKnobs((*entry)->knobs, resolved).ok());
    stress::StressCase c;
    c.name = "courtyard";
    ErrorBound b = expectedBound((*entry)->errorModel, {c, scene, resolved});
    for (const BoundTerm& t : b.terms)
        if (t.name == "fp16 colour storage")
            return {t.name, t.relative + layers * kHalfUlp16, t.absolute + layers * 6e-8, t.why};
    ADD_FAILURE() << "the model has no fp16 storage term under --hdr " << settings.text("hdr");
    return {};
}

const LedgerEntry* ledgerEntry(const RunResult& run, const std::string& name) {
    for (const LedgerEntry& e : run.memory)
        if (e.tag.name == name) return &e;
    return nullptr;
}

// Worst |h - f| / (rel * |f| + abs) over pixels and RGB; also the largest |h - f|.
struct Agreement {
    double worstRatio = 0, largest = 0;
};

Agreement agreement(const ImageRGBA& h, const ImageRGBA& f, double rel, double abs) {
    Agreement a;
    for (size_t i = 0; i < f.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c) {
            double x = h.rgba[i * 4 + c], y = f.rgba[i * 4 + c];
            a.largest = std::max(a.largest, std::abs(x - y));
            a.worstRatio = std::max(a.worstRatio, std::abs(x - y) / (rel * std::abs(y) + abs));
        }
    return a;
}

// fp16 against fp32, same scene and knobs: every fp32 value of the two runs is the same
// float up to each store (same code, same order), so what differs is the fp16 stores, and
// after a rounded store the later fp32 additions of the batches and blends ((n + 8) * 2^-24,
// the summation term). Per pixel and channel within the storage bound; the fp16 run must
// differ somewhere (the knob took effect) and its ledger hold RGBA16F targets of half the bytes.
TEST(DeferredHdr, Fp16IsFp32WithinTheStorageBound) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    struct Case {
        const char* lighting;
        uint32_t lights;
    };
    for (Case k : {Case{"tiled", 1}, Case{"tiled", 256}, Case{"volumes", 16}}) {
        Scene scene = courtyard(k.lights);
        SceneGpu gpuScene(*ctx, scene);
        for (uint32_t msaa : {1u, 4u}) {
            const std::string what = std::string(k.lighting) + " " + std::to_string(k.lights) +
                                     " lights " + std::to_string(msaa) + "x";
            RunResult f =
                runOrFail(*ctx, gpuScene, "deferred", settingsFor(msaa, "fp32", k.lighting));
            RenderSettings hs = settingsFor(msaa, "fp16", k.lighting);
            RunResult h = runOrFail(*ctx, gpuScene, "deferred", hs);
            ASSERT_EQ(h.hdr.pixelCount(), f.hdr.pixelCount());
            EXPECT_EQ(countNonFinitePixels(h.hdr), 0u) << what;
            BoundTerm bound = storageBound(scene, hs, kCourtyardBlendLayers);
            const double rel = bound.relative + (k.lights + 8.0) * kUlp32;
            Agreement a = agreement(h.hdr, f.hdr, rel, bound.absolute);
            std::printf("[ fp16 hdr ] %s: worst |fp16 - fp32| = %.3g of the bound (%.3g relative), "
                        "largest %.3g\n",
                        what.c_str(), a.worstRatio, rel, a.largest);
            EXPECT_LE(a.worstRatio, 1.0) << what << ": " << bound.why;
            EXPECT_GT(a.largest, 0.0) << what << ": --hdr fp16 changed nothing";
            for (const char* name : {"hdr", "hdr_msaa"}) {
                const LedgerEntry* e16 = ledgerEntry(h, name);
                const LedgerEntry* e32 = ledgerEntry(f, name);
                ASSERT_EQ(e16 != nullptr, msaa > 1 || std::string(name) == "hdr")
                    << what << " " << name;
                ASSERT_EQ(e32 != nullptr, e16 != nullptr);
                if (!e16) continue;
                EXPECT_EQ(e16->format, VK_FORMAT_R16G16B16A16_SFLOAT) << what << " " << name;
                EXPECT_EQ(e32->format, VK_FORMAT_R32G32B32A32_SFLOAT) << what << " " << name;
                EXPECT_EQ(2 * e16->requestedBytes, e32->requestedBytes) << what << " " << name;
            }
        }
    }
    expectNoValidationMessages(*ctx);
}

// fp16 against the reference on the courtyard (textures, masked panels, blended cloth,
// emissive strips): the fp32 bound of deferred_test.cpp (mean relative error 1e-4 at 1x and
// at 4x with --msaa-shading sample against the supersampled reference) plus the storage
// bound, whose absolute part counts relative to the metric's epsilon (1e-3).
TEST(DeferredHdr, Fp16MatchesTheReferenceWithinTheFp32BoundPlusStorage) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    for (uint32_t lights : {1u, 256u}) {
        Scene scene = courtyard(lights);
        SceneGpu gpuScene(*ctx, scene);
        for (uint32_t msaa : {1u, 4u}) {
            RenderSettings s = settingsFor(msaa, "fp16", "tiled");
            if (msaa > 1) s.set("msaa-shading", "sample");
            RunResult h = runOrFail(*ctx, gpuScene, "deferred", s);
            RunResult r = runOrFail(*ctx, gpuScene, "reference", s);
            ErrorReport e = computeError(h.hdr, r.hdr);
            BoundTerm bound = storageBound(scene, s, kCourtyardBlendLayers);
            const double limit = 1e-4 + bound.relative + bound.absolute / 1e-3;
            std::printf(
                "[ fp16 hdr ] courtyard %u lights %ux: mean relative error %.3g (limit %.3g)\n",
                lights, msaa, e.meanRelative, limit);
            EXPECT_EQ(e.nanInfCount, 0u);
            EXPECT_LT(e.meanRelative, limit) << lights << " lights " << msaa << "x";
        }
    }
    expectNoValidationMessages(*ctx);
}

// The fp32 default adds no storage term (its hdr is exact to fp32); fp16 adds one store per
// lighting batch, and the resolve of hdr_msaa in a blended scene under MSAA.
TEST(DeferredHdr, TheModelCountsTheStores) {
    Scene scene = courtyard(4);
    Result<const RendererEntry*> entry = findRenderer("deferred");
    ASSERT_TRUE(entry.ok());
    auto storeCount = [&](RenderSettings s) {
        EXPECT_TRUE(resolveKnobs((*entry)->knobs, s).ok());
        stress::StressCase c;
        ErrorBound b = expectedBound((*entry)->errorModel, {c, scene, s});
        for (const BoundTerm& t : b.terms)
            if (t.name == "fp16 colour storage") return t.relative / kHalfUlp16;
        return 0.0;
    };
    EXPECT_EQ(storeCount(settingsFor(1, "fp32", "tiled")), 0.0);
    EXPECT_DOUBLE_EQ(storeCount(settingsFor(1, "fp16", "tiled")), 1.0);
    EXPECT_DOUBLE_EQ(storeCount(settingsFor(4, "fp16", "tiled")), 2.0);   // hdr_msaa, resolve
    EXPECT_DOUBLE_EQ(storeCount(settingsFor(1, "fp16", "volumes")), 5.0); // base, 4 light blends
}

} // namespace
} // namespace tp::test
