// --gbuffer-prepass (deferred/def_settings.h): deferred's G-buffer after the pass library's depth
// prepass, testing EQUAL. The prepass keeps the nearest surface of each sample, as the G-buffer's
// own depth test does, and the masked draws' alpha test per sample, as the G-buffer's coverage
// variant does: the same surfaces, so the same image to the byte, with fewer G-buffer fragments
// (each sample's material written once). On every device both settings are forced.
#include <gtest/gtest.h>

#include <string>

#include "core/renderer/renderer.h"
#include "core/runner/frame_runner.h"
#include "gpu_test_util.h"

using namespace tp;
using namespace tp::test;

namespace {

uint64_t fragments(const RunResult& r, const std::string& pass) {
    for (const PassWork& w : r.work)
        if (w.pass == pass) return w.counts.fragmentInvocations;
    return 0;
}

} // namespace

TEST(GBufferPrepass, GivesTheImageWithoutIt) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(64, 3); // opaque, masked and blended draws
    SceneGpu gpuScene(*ctx, scene);
    struct Case {
        uint32_t msaa;
        const char* cull;
    };
    for (const Case c : {Case{1, "none"}, Case{4, "none"}, Case{1, "full"}}) {
        RenderSettings s;
        s.width = 96;
        s.height = 64;
        s.msaa = c.msaa;
        s.set("cull-geometry", c.cull);
        s.set("gbuffer-prepass", "off");
        const RunResult off = runOrFail(*ctx, gpuScene, "deferred", s);
        s.set("gbuffer-prepass", "on");
        const RunResult on = runOrFail(*ctx, gpuScene, "deferred", s);
        const std::string what = std::to_string(c.msaa) + "x --cull-geometry " + c.cull;
        EXPECT_EQ(off.hdr.rgba, on.hdr.rgba) << what;
        EXPECT_EQ(off.depth.r, on.depth.r) << what;
        EXPECT_TRUE(ranPass(on, "depth_prepass")) << what;
        EXPECT_FALSE(ranPass(off, "depth_prepass")) << what;
        EXPECT_EQ(on.stats.counter("gbuffer_prepass", -1), 1.0) << what;
        EXPECT_EQ(off.stats.counter("gbuffer_prepass", -1), 0.0) << what;
        // Each sample's material written once: no more G-buffer fragments than without it.
        if (on.statisticsCollected && c.msaa == 1) {
            EXPECT_LE(fragments(on, "gbuffer"), fragments(off, "gbuffer")) << what;
        }
    }
    expectNoValidationMessages(*ctx);
}
