// triptych info: Vulkan devices, scene statistics and features, and the plan each pipeline
// builds for this scene (passes recorded and culled, resources with the bytes allocated,
// what it left out). --print-camera: the scene's camera as a camera file.
#include <cstdio>
#include <memory>
#include <CLI/CLI.hpp>

#include "compare/commands/commands.h"
#include "core/camera/camera_file.h"
#include "core/cli/cli_common.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/runner/frame_runner.h"

namespace tp::cli {
namespace {

struct InfoOptions {
    SceneOptions scene;
    DeviceOptions device;
    ViewOptions view;
    bool devicesOnly = false;
    bool printCamera = false;
    RenderSettings knobs;
};

void printDevices() {
    Result<std::vector<DeviceInfo>> devices = GpuContext::listDevices();
    if (!devices) throw UsageError(devices.error());
    std::printf("Vulkan 1.3 devices:\n");
    for (const DeviceInfo& d : *devices)
        std::printf("  [%u] %s (%s; %s)\n", d.index, d.name.c_str(), d.type.c_str(),
                    d.driver.c_str());
    if (devices->empty()) std::printf("  none\n");
}

void printScene(const Scene& s, const SceneFeatures& f) {
    std::printf("\nScene %s\n  %zu meshes, %zu triangles, %zu vertices, %zu materials, %zu "
                "textures, %zu lights\n",
                s.source.c_str(), s.meshes.size(), s.triangleCount(), s.vertexCount(),
                s.materials.size(), s.textures.size(), s.lights.size());
    glm::vec3 e = s.bounds.extent();
    std::printf("  bounds %.2f x %.2f x %.2f\n", e.x, e.y, e.z);
    std::printf(
        "  features: blended=%d masked=%d normal_maps=%d emissive=%d textures=%d vertex_colors=%d "
        "point=%d spot=%d directional=%d\n",
        f.blended, f.masked, f.normalMaps, f.emissive, f.textures, f.vertexColors, f.pointLights,
        f.spotLights, f.directionalLights);
    std::string extensions;
    for (const std::string& e : s.extensions)
        extensions += (extensions.empty() ? "" : ", ") + e;
    std::printf("  glTF extensions decoded or applied: %s\n",
                extensions.empty() ? "none" : extensions.c_str());
    std::printf("  repairs: %zu accessor(s)\n", s.repairs.size());
    for (const SceneRepair& r : s.repairs)
        std::printf("    %s accessor %d: %zu of %zu values were %s; %s\n", r.attribute.c_str(),
                    r.accessor, r.count, r.total, r.problem.c_str(), r.action.c_str());
}

void printPlan(GpuContext& ctx, SceneGpu& scene, const RendererEntry& entry, const SceneFeatures& f,
               const RenderSettings& settings) {
    std::printf("\nPipeline %s: %s\n", entry.name.c_str(), entry.description.c_str());
    // The values were checked by the CLI (checkKnobs); planRenderer checks them once more on
    // the way to the renderer, as for every run.
    for (const Knob& k : entry.knobs)
        std::printf("  --%s %s  (%s)\n", k.name.c_str(), k.valueIn(settings.knobs).c_str(),
                    k.allowedText().c_str());
    Result<PlannedRenderer> planned = planRenderer(ctx, scene, entry, f, settings);
    if (!planned) { // that pipeline only, as in a run
        std::printf("  cannot be built here: %s\n", planned.error().c_str());
        return;
    }
    std::printf("  passes:");
    for (const std::string& p : planned->graph->livePasses())
        std::printf(" %s", p.c_str());
    for (const std::string& p : planned->graph->culledPasses())
        std::printf(" (%s: culled, output unused)", p.c_str());
    std::printf("\n");
    uint64_t total = 0;
    for (const LedgerEntry& e : ctx.ledger.entriesOf(entry.name)) {
        std::printf("  %-18s %-14s %5ux%-5u x%u %12llu bytes  %s\n", e.tag.name.c_str(),
                    formatName(e.format), e.width, e.height, e.samples, (unsigned long long)e.bytes,
                    e.tag.purpose.c_str());
        total += e.bytes;
    }
    std::printf("  total %llu bytes (%.2f bytes/pixel)\n", (unsigned long long)total,
                double(total) / (double(settings.width) * settings.height));
    for (const LeftOut& l : planned->renderer->stats().leftOut)
        std::printf("  left out: %s (%s)\n", l.what.c_str(), l.why.c_str());
}

int run(InfoOptions& o) {
    checkKnobs(o.knobs.knobs);
    if (o.printCamera) { // stdout is the camera file alone, so `> view.json` saves it; no GPU
                         // needed
        Scene scene = loadScene(o.scene);
        std::printf("%s\n", cameraToJson(scene.camera).dump(2).c_str());
        return 0;
    }
    printDevices();
    if (o.devicesOnly) return 0;
    std::unique_ptr<GpuContext> ctx = createContext(o.device);
    RenderSettings settings = makeSettings(o.view, *ctx, o.knobs);
    Scene scene = loadScene(o.scene);
    SceneFeatures f = analyzeScene(scene, settings.msaa);
    printScene(scene, f);
    std::printf("\nDevice in use: %s\n", ctx->info.name.c_str());
    SceneGpu gpuScene(*ctx, scene);
    std::printf("  shared scene data: %llu bytes\n",
                (unsigned long long)ctx->ledger.totalBytes("scene"));
    // As --cull-geometry and multipass forward's GPU light draws do before their first frame.
    gpuScene.buildMeshlets();
    std::printf("  meshlets: %u (at most 64 vertices, 124 triangles; %.1f triangles each on "
                "average), built in %.1f ms when first used (--cull-geometry, multipass "
                "forward's light draws)\n",
                gpuScene.meshletCount(),
                gpuScene.meshletCount() ? double(scene.triangleCount()) / gpuScene.meshletCount()
                                        : 0.0,
                gpuScene.meshletBuildMs());
    for (const RendererEntry& e : registeredRenderers())
        printPlan(*ctx, gpuScene, e, f, settings);
    return 0;
}

} // namespace

CommandRunner addInfoCommand(CLI::App& app) {
    auto o = std::make_shared<InfoOptions>();
    CLI::App* cmd =
        app.add_subcommand("info", "Vulkan devices, scene statistics, and each pipeline's knobs "
                                   "and plan (passes, resources, bytes) "
                                   "for these settings, without rendering");
    addSceneOptions(*cmd, o->scene);
    addViewOptions(*cmd, o->view);
    addDeviceOptions(*cmd, o->device);
    cmd->add_flag("--devices", o->devicesOnly, "List the Vulkan devices only");
    cmd->add_flag(
        "--print-camera", o->printCamera,
        "Print the scene's camera (or --camera's) as a camera file on stdout and nothing else, "
        "e.g. "
        "'triptych info builtin:courtyard --print-camera > view.json': a start for --camera");
    addKnobOptions(*cmd, o->knobs.knobs);
    return [o, cmd]() { return cmd->parsed() ? run(*o) : -1; };
}

} // namespace tp::cli
