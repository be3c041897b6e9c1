// --tile-group (core/lightassign/knobs.h): the tiled lighting's workgroup edge. A GPU runs 16 x
// 16 invocations a tile (auto), lavapipe 8 x 8; each pixel's shade and list do not depend on
// which invocation computes it, so the image must be the same bytes either way. Here, on any
// device, both edges are forced: CI on lavapipe so exercises the GPU's setting.
#include <gtest/gtest.h>

#include <string>

#include "core/renderer/renderer.h"
#include "core/runner/frame_runner.h"
#include "gpu_test_util.h"

using namespace tp;
using namespace tp::test;

namespace {

RenderSettings tileGroupSettings(uint32_t msaa, const char* group) {
    RenderSettings s;
    s.width = 96;
    s.height = 64;
    s.msaa = msaa;
    s.set("tile-group", group);
    return s;
}

} // namespace

TEST(TileGroup, SixteenGivesTheImageOfEight) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(128, 5); // blended draws: the transparent lists too
    SceneGpu gpuScene(*ctx, scene);
    struct Case {
        const char* pipeline;
        uint32_t msaa;
        const char* knob;
        const char* value;
    };
    const Case cases[] = {{"deferred", 4, "tile", "16"},
                          {"deferred", 1, "light-assign", "clustered"},
                          {"visbuffer", 1, "tile", "16"},
                          {"visbuffer", 4, "tile", "32"}};
    for (const Case& c : cases) {
        RenderSettings eight = tileGroupSettings(c.msaa, "8"), sixteen = tileGroupSettings(c.msaa, "16");
        eight.set(c.knob, c.value);
        sixteen.set(c.knob, c.value);
        const RunResult a = runOrFail(*ctx, gpuScene, c.pipeline, eight);
        const RunResult b = runOrFail(*ctx, gpuScene, c.pipeline, sixteen);
        const std::string what = std::string(c.pipeline) + " " + std::to_string(c.msaa) + "x --" +
                                 c.knob + " " + c.value;
        EXPECT_EQ(a.hdr.rgba, b.hdr.rgba) << what;
        EXPECT_GT(a.stats.counter("lights_per_tile_mean", -1), 1.0) << what; // lists to walk
    }
    expectNoValidationMessages(*ctx);
}
