// view_update_bench: the CPU cost of following a new view in place (Renderer::updateView and
// the re-recording, what RendererSession reports as view_update_ms) on the built-in courtyard:
// a session planned once (RenderSettings::manyViews), then VIEWS/2 steps of a camera orbit
// around the courtyard's target and VIEWS/2 steps of light motion. Not a test (timings on a
// shared machine make poor assertions); docs/forwardplus.md, "Many views".
//   view_update_bench [LIGHTS [WIDTH HEIGHT [VIEWS [PIPELINE [KNOB VALUE]...]]]]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "core/gpu/context.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/runner/render_session.h"
#include "core/scene/lights.h"
#include "core/scene/procedural.h"

using namespace tp;

namespace {

// Step `step` of `steps` of an orbit around the camera's target (same height).
Camera orbit(const Camera& a, int step, int steps) {
    const glm::vec3 arm = a.position - a.target;
    const float t = 6.2831853f * float(step) / float(std::max(steps, 1));
    Camera c = a;
    c.position = a.target + glm::vec3(std::cos(t) * arm.x - std::sin(t) * arm.z, arm.y,
                                      std::sin(t) * arm.x + std::cos(t) * arm.z);
    return c;
}

std::vector<Light> moved(std::vector<Light> lights, int step) {
    for (size_t i = 0; i < lights.size(); ++i)
        lights[i].position += glm::vec3(0.5f * std::sin(float(i + step)), 0.1f * float(step % 3),
                                        0.5f * std::cos(float(i * step)));
    return lights;
}

} // namespace

int main(int argc, char** argv) {
    const uint32_t lights = argc > 1 ? uint32_t(std::atol(argv[1])) : 1024;
    const uint32_t w = argc > 3 ? uint32_t(std::atol(argv[2])) : 1280,
                   h = argc > 3 ? uint32_t(std::atol(argv[3])) : 720;
    const int views = std::max(2, argc > 4 ? std::atoi(argv[4]) : 16);
    const char* pipeline = argc > 5 ? argv[5] : "forwardplus";
    Result<std::unique_ptr<GpuContext>> ctx = GpuContext::create(ContextOptions{});
    Result<Scene> scene = makeBuiltinScene("courtyard");
    Result<const RendererEntry*> entry = findRenderer(pipeline);
    if (!ctx.ok() || !scene.ok() || !entry.ok()) {
        std::fprintf(stderr, "view_update_bench: no device, scene or pipeline '%s'\n", pipeline);
        return 1;
    }
    LightGenOptions o;
    o.count = lights;
    scene->lights = generateLights(scene->bounds, o);
    RenderSettings settings;
    settings.width = w;
    settings.height = h;
    settings.manyViews = true;
    for (int i = 6; i + 1 < argc; i += 2)
        settings.knobs[argv[i]] = argv[i + 1];
    SceneGpu gpu(**ctx, *scene);
    auto session =
        RendererSession::create(**ctx, gpu, **entry, analyzeScene(*scene, 1), settings);
    if (!session.ok()) {
        std::fprintf(stderr, "view_update_bench: %s\n", session.error().c_str());
        return 1;
    }
    RunOptions once;
    once.warmupFrames = 0;
    once.timedFrames = 1;
    once.readback = false;
    const Camera a = scene->camera;
    const std::vector<Light> base = scene->lights;
    std::vector<double> ms;
    for (int v = 0; v <= views; ++v) {
        const bool lightStep = v > views / 2;
        scene->camera = orbit(a, std::min(v, views / 2), views / 2);
        if (lightStep) gpu.setLights(moved(base, v));
        Result<RunResult> r = (*session)->render(once);
        if (!r.ok()) {
            std::fprintf(stderr, "view_update_bench: %s\n", r.error().c_str());
            return 1;
        }
        const RendererStats& s = r->stats;
        const double update = s.counter("view_update_ms", -1);
        if (v > 0) ms.push_back(update);
        std::printf("view %2d %s: update %7.3f ms, frame %8.3f ms, slots needed %.0f of %.0f, "
                    "replans %.0f\n",
                    v, lightStep ? "lights" : "camera", update,
                    r->timings.empty() ? -1.0 : r->timings[0].medianMs,
                    s.counter("view_list_slots_needed", -1),
                    s.counter("view_list_slots_planned", -1), s.counter("view_replans"));
    }
    std::sort(ms.begin(), ms.end());
    std::printf("%s on %s: view_update_ms median %.3f, max %.3f over %zu views\n", pipeline,
                (*ctx)->info.name.c_str(), ms[ms.size() / 2], ms.back(), ms.size());
    return 0;
}
