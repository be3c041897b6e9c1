// Forward+'s --hdr (core/renderer/hdr_knob.h) on the default device, validation on. `auto`, the
// default, keeps Forward+'s RGBA16F target (the images of before the knob, bit for bit);
// `fp32` stores the fp32 light sum as it is, so a pixel past 65,504, the largest half, keeps
// its value where fp16 saturates (issue 40, item 4: a light passing a wall on a camera path
// was off by 69,666). The scene is the stress case beyond-half-float (a 10^6 cd light 1 m
// above the floor: radiance up to 1.6e5).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/gpu/ledger.h"
#include "core/renderer/error_model.h"
#include "core/scene/stress_scenes.h"
#include "gpu_test_util.h"

namespace tp::test {
namespace {

constexpr double kHalfMax = 65504.0;

RenderSettings settingsFor(uint32_t msaa, const char* hdr) {
    RenderSettings s;
    s.width = 96;
    s.height = 64;
    s.msaa = msaa;
    if (msaa > 1) s.set("msaa-shading", "sample"); // no shading-rate term in the bound
    if (hdr) s.set("hdr", hdr);
    return s;
}

double counterOf(const RunResult& r, const std::string& name) {
    for (const auto& [n, v] : r.stats.counters)
        if (n == name) return v;
    ADD_FAILURE() << r.renderer << ": no counter " << name;
    return -1.0;
}

VkFormat hdrFormat(const RunResult& r) {
    for (const LedgerEntry& e : r.memory)
        if (e.tag.name == "hdr") return e.format;
    ADD_FAILURE() << r.renderer << ": no hdr in the ledger";
    return VK_FORMAT_UNDEFINED;
}

// Forward+'s registered model for these settings (knobs resolved), in the stress case.
ErrorBound modelBound(const stress::StressCase& c, const Scene& scene, const RenderSettings& s) {
    Result<const RendererEntry*> entry = findRenderer("forwardplus");
    EXPECT_TRUE(entry.ok());
    RenderSettings resolved = s;
    EXPECT_TRUE(resolveKnobs((*entry)->knobs, resolved).ok());
    return expectedBound((*entry)->errorModel, {c, scene, resolved});
}

// Worst |p - r| / (relative |r| + absolute) over the channels where the reference is past
// 65,504 (`beyond`) or not; and how many channels are past it.
struct Worst {
    double beyond = 0, within = 0;
    double largestBeyond = 0; // largest |p - r| where r > 65,504
    size_t channelsBeyond = 0;
};

Worst worst(const ImageRGBA& p, const ImageRGBA& r, const ErrorBound& b) {
    Worst w;
    for (size_t i = 0; i < r.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double x = p.rgba[i * 4 + c], y = r.rgba[i * 4 + c];
            const double d = std::isfinite(x) ? std::abs(x - y) : INFINITY;
            const double ratio = d / (b.relative() * std::abs(y) + b.absolute());
            if (y > kHalfMax) {
                ++w.channelsBeyond;
                w.beyond = std::max(w.beyond, ratio);
                w.largestBeyond = std::max(w.largestBeyond, d);
            } else {
                w.within = std::max(w.within, ratio);
            }
        }
    return w;
}

// fp32 meets the reference within Forward+'s model everywhere, past 65,504 too; fp16 (and
// auto) saturates there, far beyond its bound, and holds it elsewhere (at 1x). Before the
// knob, Forward+ ignored --hdr: 306 channels past 65,504 at 1x, worst 589 times the bound.
TEST(ForwardPlusHdr, Fp32KeepsRadiancePastTheLargestHalf) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Result<std::vector<const stress::StressCase*>> cases =
        stress::selectStressCases("beyond-half-float");
    ASSERT_TRUE(cases.ok()) << cases.error();
    const stress::StressCase& c = *cases->front();
    const Scene scene = c.build();
    SceneGpu gpuScene(*ctx, scene);
    for (uint32_t msaa : {1u, 4u}) {
        const std::string at = std::to_string(msaa) + "x";
        const RunResult ref = runOrFail(*ctx, gpuScene, "reference", settingsFor(msaa, nullptr));
        const RunResult f32 = runOrFail(*ctx, gpuScene, "forwardplus", settingsFor(msaa, "fp32"));
        const RunResult f16 = runOrFail(*ctx, gpuScene, "forwardplus", settingsFor(msaa, "fp16"));
        EXPECT_EQ(hdrFormat(f32), VK_FORMAT_R32G32B32A32_SFLOAT) << at;
        EXPECT_EQ(hdrFormat(f16), VK_FORMAT_R16G16B16A16_SFLOAT) << at;
        EXPECT_EQ(counterOf(f32, "hdr_storage_bits_per_channel"), 32.0) << at;
        EXPECT_EQ(counterOf(f16, "hdr_storage_bits_per_channel"), 16.0) << at;

        const ErrorBound b32 = modelBound(c, scene, settingsFor(msaa, "fp32"));
        const ErrorBound b16 = modelBound(c, scene, settingsFor(msaa, "fp16"));
        ASSERT_TRUE(b32.bounded && b16.bounded);
        const Worst w32 = worst(f32.hdr, ref.hdr, b32), w16 = worst(f16.hdr, ref.hdr, b16);
        std::printf("[ fp+ hdr ] beyond-half-float %s: %zu channels past 65,504; fp32 worst "
                    "|d|/bound %.3g there (largest |d| %.3g), %.3g elsewhere; fp16 %.3g there "
                    "(largest |d| %.3g), %.3g elsewhere\n",
                    at.c_str(), w32.channelsBeyond, w32.beyond, w32.largestBeyond, w32.within,
                    w16.beyond, w16.largestBeyond, w16.within);
        ASSERT_GT(w32.channelsBeyond, 0u) << at << ": the case no longer passes 65,504";
        EXPECT_LE(w32.beyond, 1.0) << at << ": fp32 past 65,504";
        EXPECT_LE(w32.within, 1.0) << at << ": fp32 below 65,504";
        // Under MSAA a pixel whose mean is below 65,504 can hold a sample above it, which fp16
        // saturates: the fp16 check below it is at 1x.
        if (msaa == 1) {
            EXPECT_LE(w16.within, 1.0) << at << ": fp16 below 65,504";
        }
        EXPECT_GT(w16.beyond, 1.0) << at << ": fp16 no longer saturates";
        for (size_t i = 0; i < f16.hdr.rgba.size(); ++i)
            ASSERT_LE(f16.hdr.rgba[i], kHalfMax) << at << ": fp16 channel " << i;
    }
    expectNoValidationMessages(*ctx);
}

// --hdr auto is each pipeline's own storage: Forward+'s RGBA16F (its image that of fp16 bit for
// bit, its model fp16's), deferred's and the visibility buffer's RGBA32F; the counter says
// which each used.
TEST(ForwardPlusHdr, AutoIsEachPipelinesOwnStorage) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(16, 11);
    SceneGpu gpuScene(*ctx, scene);
    const RunResult autoRun = runOrFail(*ctx, gpuScene, "forwardplus", settingsFor(1, nullptr));
    const RunResult f16 = runOrFail(*ctx, gpuScene, "forwardplus", settingsFor(1, "fp16"));
    EXPECT_EQ(hdrFormat(autoRun), VK_FORMAT_R16G16B16A16_SFLOAT);
    EXPECT_EQ(counterOf(autoRun, "hdr_storage_bits_per_channel"), 16.0);
    EXPECT_EQ(autoRun.hdr.rgba, f16.hdr.rgba);
    for (const char* pipeline : {"deferred", "visbuffer"}) {
        const RunResult run = runOrFail(*ctx, gpuScene, pipeline, settingsFor(1, nullptr));
        EXPECT_EQ(hdrFormat(run), VK_FORMAT_R32G32B32A32_SFLOAT) << pipeline;
        EXPECT_EQ(counterOf(run, "hdr_storage_bits_per_channel"), 32.0) << pipeline;
    }
    stress::StressCase c;
    c.name = "courtyard";
    auto storage = [&](const char* hdr) {
        for (const BoundTerm& t : modelBound(c, scene, settingsFor(4, hdr)).terms)
            if (t.name == "fp16 colour storage") return t.relative / kHalfUlp16;
        return 0.0;
    };
    EXPECT_DOUBLE_EQ(storage(nullptr), 2.0); // sample, resolve
    EXPECT_DOUBLE_EQ(storage("fp16"), 2.0);
    EXPECT_EQ(storage("fp32"), 0.0);
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
