// Every configuration gives the same image on every run: each registered pipeline, each
// --light-cull and --light-assign pair where it reads them (and the other knobs below that
// change an order), 1x and 4x, rendered twice in one process and compared byte for byte (the
// HDR as read back). The pipelines come from the registry: a new one is in this test as it is
// registered.
//
// A difference between two runs comes from an order the device picks: an atomic append whose
// order becomes the order of a floating-point sum (deferred's transparent index lists were the
// last, docs/deferred.md). The visibility buffer appends its blended fragments with an atomic
// counter too (shaders/visbuffer/blended_ids.frag), but its resolve walks each pixel's list in
// ascending id order (vis_blend.glsl: nextFragment), so the append order never reaches a sum;
// only a pool too small for the fragments (--vis-blended-capacity N, counted as
// blended_fragments_dropped) would make which fragments are kept depend on it, and the default
// sizes the pool so that none is dropped. Lavapipe runs a workgroup's invocations in one fixed
// order, so on it this test proves little: it passed there with the atomic append too. It is
// for a GPU, run alone with
//   triptych_gpu_tests --gtest_filter='Determinism.*'
// (on a GPU the defaults take the GPU paths: --light-bin auto bins on the GPU, --cull-by auto
// culls by subgroup). What lavapipe can check, that the lists are in ascending order, is
// Deferred.TransparentIndexListsHoldTheirLightsInAscendingOrder.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "gpu_test_util.h"

namespace tp::test {
namespace {

struct Config {
    std::string pipeline;
    std::vector<std::pair<std::string, std::string>> knobs;
};

std::string describe(const Config& c, uint32_t msaa) {
    std::string s = c.pipeline + " " + std::to_string(msaa) + "x";
    for (const auto& [k, v] : c.knobs)
        s += " --" + k + " " + v;
    return s;
}

const Knob* knobOf(const RendererEntry& e, const std::string& name) {
    for (const Knob& k : e.knobs)
        if (k.name == name) return &k;
    return nullptr;
}

// Every registered renderer; where it reads --light-cull and --light-assign, every pair of
// their values (deferred: tiled lighting, and volumes with its lists-only pass); and, for the
// renderers that read them, Forward+'s linked lists (nodes allocated with an atomic add,
// chained in light order; tiled only), its subgroup light loop (clustered only) and the
// visibility buffer's hybrid forward pass for blended surfaces.
std::vector<Config> configurations() {
    std::vector<Config> out;
    for (const RendererEntry& e : registeredRenderers()) {
        const Knob* cull = knobOf(e, "light-cull");
        const Knob* assign = knobOf(e, "light-assign");
        if (cull && assign) {
            for (const std::string& c : cull->values)
                for (const std::string& a : assign->values)
                    if (c != "auto") // resolves to one of the others
                        out.push_back({e.name, {{"light-cull", c}, {"light-assign", a}}});
        } else {
            out.push_back({e.name, {}});
        }
        if (knobOf(e, "light-lists")) out.push_back({e.name, {{"light-lists", "linked"}}});
        if (knobOf(e, "light-loop"))
            out.push_back({e.name, {{"light-assign", "clustered"}, {"light-loop", "subgroup"}}});
        if (knobOf(e, "deferred-lighting"))
            for (const std::string& c : cull ? cull->values : std::vector<std::string>{})
                if (c != "auto")
                    out.push_back({e.name, {{"deferred-lighting", "volumes"}, {"light-cull", c}}});
        if (knobOf(e, "vis-blended")) out.push_back({e.name, {{"vis-blended", "forward"}}});
    }
    return out;
}


// The courtyard-small (blended cloth, masked panels, emissive), 256 lights at 96x64 (24 tiles
// of 16 pixels, tens of lights in a tile's lists); on lavapipe 407 s in all with ViewUpdate
// run beside it on 2 shared cores (the ctest TIMEOUT is 600 s).
TEST(Determinism, EveryConfigurationRendersTheSameBytesTwice) {
    // A knob renamed or gone would drop its configurations without a word: each must still be
    // read by some renderer.
    for (const char* knob : {"light-cull", "light-lists", "light-loop", "deferred-lighting",
                             "vis-blended"})
        EXPECT_TRUE(std::any_of(registeredRenderers().begin(), registeredRenderers().end(),
                                [&](const RendererEntry& e) { return knobOf(e, knob); }))
            << "no renderer reads --" << knob;
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
            const size_t n = differingPixels(first.hdr, second.hdr, &at);
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
