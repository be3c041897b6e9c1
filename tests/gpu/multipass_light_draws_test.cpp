// Multipass forward's per-light draw lists on the GPU (--light-draws gpu, the default:
// multipass_forward/light_draw_pass.h; gpu-blended, the blended draws' lights too:
// blended_light_draw_pass.h) against the CPU's lists (--light-draws cpu, the light plan as it was
// built before): the same images bit for bit and the same counters, at 1x and 4x at both shading
// rates, with meshlet culling, shadows, fp16 and every --blended-lights; and, over several views
// of one planned renderer, no per-light list (opaque or blended) built on the CPU while the
// counters stay those of a CPU plan of each view.
#include <cstring>

#include "core/cli/shadow_option.h"
#include "core/runner/render_session.h"
#include "core/scene/meshlets.h"
#include "gpu_test_util.h"

// Named: the GPU tests build as unity files, where other tests' anonymous helpers are visible.
namespace tp::test::mp_light_draws {
namespace {

// The counters the light plan gives, which the GPU lists must give alike (after the frame).
const char* const kPlanCounters[] = {"lights_skipped",      "meshes_per_light_mean",
                                     "meshes_per_light_max", "light_passes_draws",
                                     "blended_light_draws",  "blended_draws",
                                     "local_lights",         "draws"};

struct Config {
    std::string name;
    uint32_t msaa = 1;
    std::map<std::string, std::string> knobs;
    const char* shadows = nullptr;
    // The blended draws' lights on the GPU too: --blended-lights under (the default) without
    // shadows (additive and shadows keep them on the CPU; one-pass has none).
    bool blendedOnGpu() const {
        auto b = knobs.find("blended-lights");
        return !shadows && (b == knobs.end() || b->second == "under");
    }
};

void PrintTo(const Config& c, std::ostream* os) {
    *os << c.name;
}

// The courtyard with point lights, six directional ones (two beyond the base pass's four:
// full-screen light passes, TP_MPLD_FLAG_ALL) and one light behind the camera.
Scene sceneWithLights() {
    Scene s = courtyardSmallWithLights(40, 11);
    for (int i = 0; i < 6; ++i) {
        Light d;
        d.type = LightType::Directional;
        d.direction = glm::normalize(glm::vec3(0.3f * float(i) - 0.7f, -1.0f, 0.2f * float(i)));
        d.color = glm::vec3(1.0f, 0.9f, 0.8f);
        d.intensity = 0.2f;
        s.lights.push_back(d);
    }
    // And one behind the camera, which every list skips.
    Light behind;
    behind.position = s.camera.position + 3.0f * glm::normalize(s.camera.position - s.camera.target);
    behind.range = 0.5f;
    s.lights.push_back(behind);
    return s;
}

RunResult render(GpuContext& ctx, const Scene& scene, const Config& c, const char* lists) {
    RenderSettings s;
    s.width = 96;
    s.height = 64;
    s.msaa = c.msaa;
    s.knobs = c.knobs;
    s.knobs["light-draws"] = lists;
    if (c.shadows) s.shadows = parseShadowCount(c.shadows);
    SceneGpu gpu(ctx, scene);
    return runOrFail(ctx, gpu, "multipass_forward", s);
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && !a.empty() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

class MultipassLightDraws : public ::testing::TestWithParam<Config> {};

TEST_P(MultipassLightDraws, GpuListsRenderTheCpuListsImageWithTheirCounters) {
    const Config& c = GetParam();
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const Scene scene = sceneWithLights();
    const RunResult cpu = render(*ctx, scene, c, "cpu");
    // gpu: the opaque lists on the GPU, the blended lights recorded per view as on the CPU.
    const RunResult opaque = render(*ctx, scene, c, "gpu");
    EXPECT_EQ(opaque.stats.counter("light_draws_gpu"), 1.0) << "fell back to the CPU";
    EXPECT_EQ(opaque.stats.counter("blended_light_draws_gpu", -1), 0.0);
    EXPECT_TRUE(sameBits(opaque.hdr.rgba, cpu.hdr.rgba))
        << c.name << ": gpu's colour differs in " << differingPixels(opaque.hdr, cpu.hdr) << " pixels";
    for (const char* name : kPlanCounters)
        EXPECT_EQ(opaque.stats.counter(name, -1), cpu.stats.counter(name, -2)) << c.name << ": " << name;
    const RunResult gpu = render(*ctx, scene, c, "gpu-blended");
    EXPECT_EQ(gpu.stats.counter("light_draws_gpu"), 1.0) << "fell back to the CPU";
    EXPECT_EQ(cpu.stats.counter("light_draws_gpu"), 0.0);
    EXPECT_EQ(gpu.stats.counter("blended_light_draws_gpu", -1), c.blendedOnGpu() ? 1.0 : 0.0);
    EXPECT_EQ(cpu.stats.counter("blended_light_draws_gpu", -1), 0.0);
    // GPU blended lists: the plan tested no blended draw against a light on the CPU.
    const bool onePass = c.knobs.count("blended-lights") && c.knobs.at("blended-lights") == "one-pass";
    EXPECT_EQ(gpu.stats.counter("blended_light_lists_cpu_builds", -1),
              c.blendedOnGpu() || onePass ? 0.0 : 1.0);
    if (c.blendedOnGpu()) {
        EXPECT_GT(cpu.stats.counter("blended_light_draws"), 0.0) << "no blended light: weak";
    }
    EXPECT_TRUE(sameBits(gpu.hdr.rgba, cpu.hdr.rgba))
        << c.name << ": colour differs in " << differingPixels(gpu.hdr, cpu.hdr) << " pixels";
    EXPECT_TRUE(sameBits(gpu.depth.r, cpu.depth.r)) << c.name << ": depth differs";
    for (const char* name : kPlanCounters)
        EXPECT_EQ(gpu.stats.counter(name, -1), cpu.stats.counter(name, -2)) << c.name << ": " << name;
    EXPECT_GT(cpu.stats.counter("light_passes_draws"), 0.0);
    EXPECT_GT(cpu.stats.counter("lights_skipped"), 0.0) << "no light is skipped: a weak check";
    expectNoValidationMessages(*ctx);
}

INSTANTIATE_TEST_SUITE_P(
    Configs, MultipassLightDraws,
    ::testing::Values(Config{"1x"}, Config{"4x_pixel", 4, {{"msaa-shading", "pixel"}}},
                      Config{"4x_sample", 4, {{"msaa-shading", "sample"}}},
                      Config{"1x_additive", 1, {{"blended-lights", "additive"}}},
                      Config{"1x_one_pass", 1, {{"blended-lights", "one-pass"}}},
                      Config{"1x_fp16", 1, {{"accum", "fp16"}}},
                      Config{"1x_cull_frustum", 1, {{"cull-geometry", "frustum"}}},
                      Config{"4x_cull_full", 4, {{"cull-geometry", "full"}}},
                      Config{"1x_shadows", 1, {}, "3"},
                      Config{"4x_shadows_cull", 4, {{"cull-geometry", "frustum"}}, "all"}),
    [](const ::testing::TestParamInfo<Config>& info) { return info.param.name; });

// A device without dual-source blending keeps the blended draws' lights on the CPU, says so in
// left_out, and renders the same image (the opaque lists stay on the GPU).
TEST(MultipassLightDrawsFallback, WithoutDualSourceBlendingBlendedLightsStayOnTheCpu) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const Scene scene = sceneWithLights();
    const RunResult cpu = render(*ctx, scene, Config{"1x"}, "cpu");
    ctx->caps.dualSrcBlend = false; // as a device without the feature reports it
    const RunResult gpu = render(*ctx, scene, Config{"1x"}, "gpu-blended");
    EXPECT_EQ(gpu.stats.counter("light_draws_gpu"), 1.0);
    EXPECT_EQ(gpu.stats.counter("blended_light_draws_gpu", -1), 0.0);
    EXPECT_EQ(gpu.stats.counter("blended_light_lists_cpu_builds", -1), 1.0);
    bool said = false;
    for (const LeftOut& l : gpu.stats.leftOut)
        said |= l.what.find("blended_light_draws") != std::string::npos &&
                l.why.find("dualSrcBlend") != std::string::npos;
    EXPECT_TRUE(said) << "left_out does not say why the blended lights stay on the CPU";
    EXPECT_TRUE(sameBits(gpu.hdr.rgba, cpu.hdr.rgba));
    for (const char* name : kPlanCounters)
        EXPECT_EQ(gpu.stats.counter(name, -1), cpu.stats.counter(name, -2)) << name;
    expectNoValidationMessages(*ctx);
}

// Triangles of the meshlets (core/scene/meshlets.h) of every opaque and masked mesh whose sphere
// a light at `centre` with range `range` reaches, the reach scaled by `scale`; and of the meshes
// its sphere reaches at all (their boxes), whole.
struct Reach {
    double meshlets = 0, meshes = 0;
};
Reach reachedTriangles(const Scene& scene, glm::vec3 centre, float range, float scale) {
    Reach r;
    for (const Mesh& mesh : scene.meshes) {
        if (scene.materials[mesh.material].alphaMode == AlphaMode::Blend) continue;
        const glm::vec3 nearest = glm::clamp(centre, mesh.bounds.min, mesh.bounds.max);
        if (glm::length(centre - nearest) > range) continue;
        r.meshes += double(mesh.indices.size() / 3);
        for (const Meshlet& m : buildMeshlets(mesh).meshlets)
            if (glm::length(m.center - centre) <= (range + m.radius) * scale)
                r.meshlets += m.triangleCount;
    }
    return r;
}

// light_draws.comp draws, of each mesh a light touches, only the runs of meshlets its sphere
// reaches: one small light by the courtyard's floor submits the triangles of the meshlets a
// CPU count says it reaches (to a rounding of the reach), far fewer than its meshes hold, and
// the image is the CPU lists' (whole meshes) bit for bit: what is left out adds exactly 0.
TEST(MultipassLightDrawsMeshlets, ALightDrawsOnlyTheMeshletsItReaches) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = courtyardSmallWithLights(0, 1);
    const float diagonal = glm::length(scene.bounds.max - scene.bounds.min);
    Light l;
    l.position = scene.camera.target + glm::vec3(0.0f, 0.02f * diagonal, 0.0f);
    l.range = 0.06f * diagonal;
    l.intensity = 20.0f;
    scene.lights = {l};
    const RunResult cpu = render(*ctx, scene, Config{"1x"}, "cpu");
    const RunResult gpu = render(*ctx, scene, Config{"1x"}, "gpu");
    ASSERT_EQ(gpu.stats.counter("light_draws_gpu"), 1.0);
    EXPECT_TRUE(sameBits(gpu.hdr.rgba, cpu.hdr.rgba))
        << "colour differs in " << differingPixels(gpu.hdr, cpu.hdr) << " pixels";
    const double submitted = gpu.stats.counter("light_passes_triangles", -1);
    const Reach inner = reachedTriangles(scene, l.position, l.range, 0.999f);
    const Reach outer = reachedTriangles(scene, l.position, l.range, 1.001f);
    std::printf("[ light draws ] one light: %.0f triangles submitted, its meshlets %.0f-%.0f, "
                "its meshes %.0f\n",
                submitted, inner.meshlets, outer.meshlets, outer.meshes);
    EXPECT_GT(inner.meshlets, 0.0) << "the light reaches no meshlet: a weak test";
    EXPECT_GE(submitted, inner.meshlets);
    EXPECT_LE(submitted, outer.meshlets);
    EXPECT_LT(outer.meshlets, 0.7 * outer.meshes) << "its meshes are hardly larger: a weak test";
    expectNoValidationMessages(*ctx);
}

// A renderer planned once and moved through an orbit: with GPU lists no view builds a per-light
// list on the CPU (light_lists_cpu_builds stays 0; with cpu it counts every view), and each
// view's counters are those of a CPU plan made at that view.
TEST(MultipassLightDrawsViews, NoViewBuildsPerLightListsOnTheCpu) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene scene = sceneWithLights();
    const Camera a = scene.camera;
    RenderSettings settings;
    settings.width = 96;
    settings.height = 64;
    settings.manyViews = true;
    std::map<std::string, std::unique_ptr<RendererSession>> sessions;
    Result<const RendererEntry*> entry = findRenderer("multipass_forward");
    ASSERT_TRUE(entry.ok());
    SceneGpu gpu(*ctx, scene);
    for (const char* lists : {"gpu-blended", "cpu"}) {
        RenderSettings s = settings;
        s.knobs["light-draws"] = lists;
        auto session = RendererSession::create(*ctx, gpu, **entry, analyzeScene(scene, 1), s);
        ASSERT_TRUE(session.ok()) << session.error();
        sessions[lists] = std::move(*session);
    }
    RunOptions once;
    once.warmupFrames = 0;
    once.timedFrames = 1;
    const int views = 4;
    for (int v = 0; v < views; ++v) {
        scene.camera = a;
        scene.camera.position += glm::vec3(-0.8f * float(v), -0.2f * float(v), 0.5f * float(v));
        Result<RunResult> g = sessions["gpu-blended"]->render(once);
        Result<RunResult> c = sessions["cpu"]->render(once);
        ASSERT_TRUE(g.ok() && c.ok());
        EXPECT_EQ(g->stats.counter("light_lists_cpu_builds", -1), 0.0) << "view " << v;
        EXPECT_EQ(c->stats.counter("light_lists_cpu_builds", -1), double(v + 1)) << "view " << v;
        EXPECT_EQ(g->stats.counter("blended_light_lists_cpu_builds", -1), 0.0) << "view " << v;
        EXPECT_EQ(c->stats.counter("blended_light_lists_cpu_builds", -1), double(v + 1))
            << "view " << v;
        EXPECT_EQ(g->stats.counter("blended_light_draws_gpu", -1), 1.0) << "view " << v;
        EXPECT_TRUE(sameBits(g->hdr.rgba, c->hdr.rgba))
            << "view " << v << ": colour differs in " << differingPixels(g->hdr, c->hdr)
            << " pixels";
        for (const char* name : kPlanCounters)
            EXPECT_EQ(g->stats.counter(name, -1), c->stats.counter(name, -2))
                << "view " << v << ": " << name;
    }
    EXPECT_EQ(sessions["gpu-blended"]->replans(), 0u);
    EXPECT_EQ(sessions["gpu-blended"]->updates(), uint32_t(views - 1));
    expectNoValidationMessages(*ctx);
}

// A light pass's 2x2 quad beyond the light's range skips the light and the material, so the
// fragments no longer count the light evaluations. On a GPU the shader counts the fragments
// that evaluate their light (per subgroup, helpers left out): some, and never more than the
// pass's fragment invocations; on a CPU device the count is left out, saying why. Both list
// layouts (CPU lists draw the plain and count variants, GPU lists the per-instance ones).
TEST(MultipassLightCount, TheLightPassesCountTheFragmentsThatEvaluateTheirLight) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    const Scene scene = sceneWithLights();
    const bool gpu = !ctx->isCpuDevice();
    for (const char* lists : {"cpu", "gpu"}) {
        const RunResult r = render(*ctx, scene, Config{"1x"}, lists);
        const PassWork* lit = nullptr;
        for (const PassWork& w : r.work)
            if (w.pass == "light_passes") lit = &w;
        ASSERT_NE(lit, nullptr) << lists;
        bool leftOut = false;
        for (const LeftOut& l : r.stats.leftOut)
            leftOut |= l.what.find("light_passes' light evaluations") != std::string::npos;
        EXPECT_EQ(leftOut, !gpu) << lists;
        if (!gpu) {
            EXPECT_TRUE(lit->lightHow.empty()) << lists;
            continue;
        }
        EXPECT_GT(lit->lightEvaluations, 0.0) << lists;
        EXPECT_LE(lit->lightEvaluations, double(lit->counts.fragmentInvocations)) << lists;
    }
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test::mp_light_draws
