// Every configuration gives the same image on every run: each pipeline, each --light-cull and
// --light-assign mode (and deferred's lighting modes), 1x and 4x, rendered twice in one process
// and compared byte for byte (the HDR as read back).
//
// A difference between two runs comes from an order the device picks: an atomic append whose
// order becomes the order of a floating-point sum (deferred's transparent index lists were the
// last, docs/deferred.md). Lavapipe runs a workgroup's invocations in one fixed order, so on it
// this test proves little: it passed there with the atomic append too. It is for a GPU, run
// alone with
//   triptych_gpu_tests --gtest_filter='Determinism.*'
// (on a GPU the defaults take the GPU paths: --light-bin auto bins on the GPU, --cull-by auto
// culls by subgroup). What lavapipe can check, that the lists are in ascending order, is
// Deferred.TransparentIndexListsHoldTheirLightsInAscendingOrder.
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "gpu_test_util.h"

namespace tp::test {
namespace {

struct Config {
    const char* pipeline;
    std::vector<std::pair<const char*, const char*>> knobs;
};

std::string describe(const Config& c, uint32_t msaa) {
    std::string s = std::string(c.pipeline) + " " + std::to_string(msaa) + "x";
    for (const auto& [k, v] : c.knobs)
        s += std::string(" --") + k + " " + v;
    return s;
}

// Every pipeline, and for the tiled ones every light-cull x light-assign pair (deferred:
// tiled lighting, and volumes with its lists-only pass); Forward+'s linked lists (nodes
// allocated with an atomic add, chained in light order; tiled only) and its subgroup light
// loop (clustered only) too.
std::vector<Config> configurations() {
    std::vector<Config> out = {{"reference", {}}, {"multipass_forward", {}}};
    for (const char* pipeline : {"forwardplus", "deferred"})
        for (const char* cull : {"binned", "all"})
            for (const char* assign : {"tiled", "clustered"})
                out.push_back({pipeline, {{"light-cull", cull}, {"light-assign", assign}}});
    out.push_back({"forwardplus", {{"light-lists", "linked"}}});
    out.push_back({"forwardplus", {{"light-assign", "clustered"}, {"light-loop", "subgroup"}}});
    for (const char* cull : {"binned", "all"})
        out.push_back({"deferred", {{"deferred-lighting", "volumes"}, {"light-cull", cull}}});
    return out;
}

// Pixels whose RGBA bytes differ (0: identical images), and the first of them.
size_t differingPixels(const ImageRGBA& a, const ImageRGBA& b, size_t& first) {
    size_t n = 0;
    first = 0;
    for (size_t i = 0; i < a.pixelCount(); ++i)
        if (std::memcmp(&a.rgba[i * 4], &b.rgba[i * 4], 4 * sizeof(float)) != 0 && n++ == 0)
            first = i;
    return n;
}

// The courtyard-small (blended cloth, masked panels, emissive), 256 lights at 96x64 (24 tiles
// of 16 pixels, tens of lights in a tile's lists); on lavapipe about a minute in all.
TEST(Determinism, EveryConfigurationRendersTheSameBytesTwice) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(256, 29);
    SceneGpu gpuScene(*ctx, scene);
    for (uint32_t msaa : {1u, 4u}) {
        for (const Config& c : configurations()) {
            RenderSettings s;
            s.width = 96;
            s.height = 64;
            s.msaa = msaa;
            for (const auto& [k, v] : c.knobs)
                s.set(k, v);
            const std::string what = describe(c, msaa);
            const auto t0 = std::chrono::steady_clock::now();
            RunResult first = runOrFail(*ctx, gpuScene, c.pipeline, s);
            RunResult second = runOrFail(*ctx, gpuScene, c.pipeline, s);
            ASSERT_EQ(first.hdr.rgba.size(), second.hdr.rgba.size()) << what;
            size_t at = 0;
            const size_t n = differingPixels(first.hdr, second.hdr, at);
            EXPECT_EQ(n, 0u) << what << ": " << n
                             << " pixels differ between two runs, the first at " << at % s.width
                             << "," << at / s.width;
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                    .count();
            std::printf("[ determinism ] %s: %zu pixels differ (two runs: %.0f ms)\n", what.c_str(),
                        n, ms);
        }
    }
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
