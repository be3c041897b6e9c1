// Plan once, render many views (core/runner/render_session.h): a renderer planned at one view
// and moved to another renders exactly what a renderer planned at the other view renders
// (bit-identical colour and depth), for every registered renderer and the knobs that change
// what it derives from the camera and the lights.
// The session counts how it followed each change: in place (Renderer::updateView) or by
// planning again; a pipeline not in kMayReplan must never need the second way on these views.
#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <string>

#include "core/runner/render_session.h"
#include "gpu_test_util.h"

namespace tp::test {
namespace {

struct Config {
    std::string pipeline;
    std::map<std::string, std::string> knobs;
    uint32_t msaa = 1;
};

std::string nameOf(const Config& c) {
    std::string n = c.pipeline;
    for (const auto& [k, v] : c.knobs)
        n += " --" + k + " " + v;
    return n + (c.msaa > 1 ? " --msaa " + std::to_string(c.msaa) : "");
}

// The pipelines whose updateView may plan again on these views (a renderer that bakes the
// view: core/renderer/renderer.h, contract 6). None today: every other registered renderer, a
// new one included, must follow every view in place, with the test below as its proof.
const std::set<std::string> kMayReplan = {};

// The knob values that change what a renderer derives from the camera and the lights, each
// tried on every registered renderer that reads the knob.
const std::vector<std::pair<std::string, std::string>> kViewKnobs = {
    {"light-bin", "cpu"},           {"light-bin", "gpu"},          {"light-assign", "clustered"},
    {"light-lists", "linked"},      {"deferred-lighting", "volumes"},
    {"light-draws", "cpu"}, // multipass forward: its per-light lists rebuilt on the CPU per view
    {"blended-lights", "one-pass"}, {"vis-blended", "forward"},
    {"cull-geometry", "frustum"}, // the meshlets kept follow the camera on the GPU
    // Occlusion's history is the last view's visible set: the late phase draws what the new
    // view uncovers (the first render at B and back at A start from a stale history).
    {"cull-geometry", "full"},
};

// Combinations whose per-view work differs from each knob's alone: clustered under the GPU
// binning (the frame lays out the mask rows too: docs/forwardplus.md, "Many views").
const std::vector<std::map<std::string, std::string>> kViewKnobSets = {
    {{"light-assign", "clustered"}, {"light-bin", "gpu"}},
};

bool reads(const RendererEntry& e, const std::string& knob) {
    return std::any_of(e.knobs.begin(), e.knobs.end(),
                       [&](const Knob& k) { return k.name == knob; });
}

// Every registered renderer at its defaults, at 4x, and with each of kViewKnobs it reads.
std::vector<Config> configs() {
    std::vector<Config> out;
    for (const RendererEntry& e : registeredRenderers()) {
        out.push_back({e.name, {}});
        out.push_back({e.name, {}, 4});
        for (const auto& [knob, value] : kViewKnobs)
            if (reads(e, knob)) out.push_back({e.name, {{knob, value}}});
        for (const auto& set : kViewKnobSets)
            if (std::all_of(set.begin(), set.end(),
                            [&](const auto& kv) { return reads(e, kv.first); }))
                out.push_back({e.name, set});
    }
    return out;
}

// The courtyard's own camera, a second view from elsewhere looking elsewhere (through the
// colonnade), and the lights each moved by a seeded offset (same count, same types).
Camera movedCamera(const Camera& a) {
    Camera b = a;
    b.position = a.position + glm::vec3(-2.5f, -0.6f, 1.5f);
    b.target = a.target + glm::vec3(1.0f, 0.3f, -2.0f);
    return b;
}

std::vector<Light> movedLights(std::vector<Light> lights) {
    for (size_t i = 0; i < lights.size(); ++i)
        lights[i].position += glm::vec3(0.4f * std::sin(float(i)), 0.1f, 0.4f * std::cos(float(i)));
    return lights;
}

RunResult freshRun(GpuContext& ctx, Scene& scene, const RendererEntry& entry,
                   const RenderSettings& settings) {
    SceneGpu gpu(ctx, scene);
    RunOptions once;
    once.warmupFrames = 0;
    once.timedFrames = 1;
    Result<RunResult> r =
        runRenderer(ctx, gpu, entry, analyzeScene(scene, settings.msaa), settings, once);
    EXPECT_TRUE(r.ok()) << r.error();
    return r.ok() ? std::move(*r) : RunResult{};
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && !a.empty() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

void expectSameImages(const RunResult& moved, const RunResult& fresh, const std::string& what) {
    EXPECT_TRUE(sameBits(moved.hdr.rgba, fresh.hdr.rgba)) << what << ": colour differs";
    EXPECT_TRUE(sameBits(moved.depth.r, fresh.depth.r)) << what << ": depth differs";
}

void PrintTo(const Config& c, std::ostream* os) {
    *os << nameOf(c);
}

class ViewUpdate : public ::testing::TestWithParam<Config> {};

TEST_P(ViewUpdate, AMovedRendererRendersWhatOnePlannedThereRenders) {
    const Config& c = GetParam();
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(24, 7);
    const Camera a = scene.camera, b = movedCamera(a);
    const std::vector<Light> lightsA = scene.lights, lightsB = movedLights(lightsA);
    RenderSettings settings;
    settings.width = 96;
    settings.height = 64;
    settings.msaa = c.msaa;
    settings.knobs = c.knobs;
    settings.manyViews = true;
    Result<const RendererEntry*> entry = findRenderer(c.pipeline);
    ASSERT_TRUE(entry.ok());

    SceneGpu gpu(*ctx, scene);
    auto session = RendererSession::create(*ctx, gpu, **entry,
                                           analyzeScene(scene, c.msaa), settings);
    ASSERT_TRUE(session.ok()) << session.error();
    RunOptions once;
    once.warmupFrames = 0;
    once.timedFrames = 1;
    const std::vector<Light>* current = &lightsA; // what `gpu` holds
    auto renderAt = [&](const Camera& cam, const std::vector<Light>& lights) {
        scene.camera = cam;
        if (&lights != current) gpu.setLights(lights);
        current = &lights;
        Result<RunResult> r = (*session)->render(once);
        EXPECT_TRUE(r.ok()) << r.error();
        return r.ok() ? std::move(*r) : RunResult{};
    };
    const RunResult atA = renderAt(a, lightsA);
    const RunResult atB = renderAt(b, lightsA);
    const RunResult backAtA = renderAt(a, lightsA);
    const RunResult lightsMoved = renderAt(b, lightsB);

    expectSameImages(backAtA, atA, nameOf(c) + " back at A");
    scene.camera = b;
    scene.lights = lightsA;
    expectSameImages(atB, freshRun(*ctx, scene, **entry, settings), nameOf(c) + " at B");
    scene.lights = lightsB;
    expectSameImages(lightsMoved, freshRun(*ctx, scene, **entry, settings),
                     nameOf(c) + " lights moved");
    EXPECT_EQ((*session)->updates() + (*session)->replans(), 3u);
    if (!kMayReplan.count(c.pipeline)) {
        EXPECT_EQ((*session)->replans(), 0u) << nameOf(c);
    }
    EXPECT_GE(lightsMoved.stats.counter("view_update_ms", -1.0), 0.0);
    expectNoValidationMessages(*ctx);
}

// A knob of kViewKnobs renamed or gone would drop its configurations without a word.
TEST(ViewUpdateKnobs, EveryViewKnobIsReadBySomeRenderer) {
    for (const auto& [knob, value] : kViewKnobs)
        EXPECT_TRUE(std::any_of(registeredRenderers().begin(), registeredRenderers().end(),
                                [&](const RendererEntry& e) { return reads(e, knob); }))
            << "no renderer reads --" << knob;
    for (const auto& set : kViewKnobSets)
        EXPECT_TRUE(std::any_of(registeredRenderers().begin(), registeredRenderers().end(),
                                [&](const RendererEntry& e) {
                                    return std::all_of(set.begin(), set.end(), [&](const auto& kv) {
                                        return reads(e, kv.first);
                                    });
                                }))
            << "no renderer reads the whole set";
}

INSTANTIATE_TEST_SUITE_P(EveryPipeline, ViewUpdate, ::testing::ValuesIn(configs()),
                         [](const ::testing::TestParamInfo<Config>& info) {
                             std::string n = nameOf(info.param);
                             for (char& ch : n)
                                 if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                             return n;
                         });

} // namespace
} // namespace tp::test
