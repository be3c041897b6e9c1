// triptych render: one pipeline, one image (linear EXR + tonemapped PNG), its timings,
// memory and statistics (render.json), the lights used (lights.json) and the camera used
// (camera.json, a --camera file).
#include <cstdio>
#include <memory>
#include <CLI/CLI.hpp>

#include "compare/cache/calibration_cache.h"
#include "compare/commands/commands.h"
#include "compare/commands/path_options.h"
#include "compare/report/run_json.h"
#include "core/camera/camera_file.h"
#include "core/cli/cli_common.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/image/image_io.h"
#include "core/image/metrics.h"
#include "core/image/tonemap.h"
#include "core/reference/reference_renderer.h"
#include "core/energy/energy_text.h"
#include "core/runner/device_energy.h"
#include "core/runner/frame_runner.h"
#include "core/util/files.h"

namespace tp::cli {
namespace {

struct RenderOptions {
    SceneOptions scene;
    DeviceOptions device;
    ViewOptions view;
    std::string pipeline = kReferenceRenderer;
    std::string out = "out";
    int frames = 3;
    int warmup = 1;
    std::string exposure = "auto";
    std::string exrType = "float";
    std::string calibration = "auto";
    bool passStatistics = true; // --pass-statistics
    PathOptions path; // --camera-path / --light-motion: the path's timings, then view 0's image
    RenderSettings knobs;
};

void writeOutputs(const RenderOptions& o, const Scene& scene, const CameraSource& camera,
                  const RunResult& run, const GpuContext& ctx, const RenderSettings& settings,
                  const SceneFeatures& features, const RunCalibration& calibration,
                  const EnergySource& energy, const nlohmann::json& path) {
    const std::string base = o.out + "/" + run.renderer;
    float ev = parseExposure(o.exposure, run.hdr);
    Status s = writeExr(base + ".exr", run.hdr,
                        o.exrType == "half" ? ExrPixelType::Half : ExrPixelType::Float);
    if (s) s = writePng(base + ".png", tonemapToDisplay(run.hdr, ev));
    if (s) s = writeLightsFile(o.out + "/lights.json", scene.lights);
    if (s) s = writeCameraFile(o.out + "/camera.json", scene.camera); // ready for --camera
    for (const DebugImage& d : run.debugImages) {
        if (!s) break;
        const std::string path = base + "_debug_" + d.name;
        s = d.display ? writePng(path + ".png", d.image)
                      : writeExr(path + ".exr", d.image, ExrPixelType::Float);
    }
    nlohmann::json j;
    j["schema"] = "triptych.render/2";
    j["device"] = deviceJson(ctx);
    j["settings"] = settingsJson(settings);
    j["settings"]["exposure_ev"] = ev;
    j["settings"]["seed"] = o.scene.seed;
    j["scene"] = sceneJson(scene, features);
    j["camera"] = cameraToJson(scene.camera);
    j["camera_source"] = cameraSourceJson(camera);
    j["run"] = runJson(run, ctx);
    j["calibration"] = calibrationUseJson(calibration);
    j["energy_source"] = energySourceJson(energy);
    j["nan_inf_pixels"] = countNonFinitePixels(run.hdr);
    if (!path.is_null()) j["path"] = path;
    if (s) s = writeTextFile(o.out + "/render.json", j.dump(2) + "\n");
    if (!s) throw UsageError(s.error());
}

// With --camera-path or --light-motion: the timing pass over the path (compare/measure/path_run.h),
// its percentiles on stderr; the scene is left at view 0 for the image. Null without a path.
nlohmann::json renderPath(const RenderOptions& o, const std::optional<PathInput>& path,
                          Scene& scene, SceneGpu& gpuScene, GpuContext& ctx,
                          const SceneFeatures& features, const RenderSettings& settings) {
    if (!path) return nullptr;
    PathRunSetup setup{ctx, scene, gpuScene, features, settings, {o.pipeline}, o.warmup, o.frames,
                       o.exposure};
    std::fprintf(stderr, "triptych: path %s: %zu views, lights %s\n", path->source.c_str(),
                 path->views.size(), path->lightMotion.c_str());
    PathSeries series = timePath(setup, *path, o.pipeline);
    if (!series.error.empty()) throw UsageError(series.error);
    applyPathView(scene, gpuScene, *path, 0);
    nlohmann::json j = seriesJson(series);
    j["source"] = path->source;
    j["views"] = path->views.size();
    j["light_motion"] = path->lightMotion;
    const nlohmann::json& f = j["summary"]["frame_ms"];
    std::fprintf(stderr,
                 "triptych: path frame ms on %s: median %.3f, p95 %.3f, p99 %.3f, max %.3f; "
                 "%u views followed in place, %u planned again\n",
                 ctx.info.name.c_str(), f["median"].get<double>(), f["p95"].get<double>(),
                 f["p99"].get<double>(), f["max"].get<double>(), series.updates, series.replans);
    return j;
}

int run(RenderOptions& o) {
    checkFrameCounts(o.frames, o.warmup);
    checkKnobs(o.knobs.knobs);
    Result<const RendererEntry*> entry = findRenderer(o.pipeline);
    if (!entry) throw UsageError("--pipeline: " + entry.error());
    if (o.exposure != "auto") parseExposure(o.exposure, ImageRGBA{}); // refuse before rendering
    if (!o.scene.cameraFile.empty()) readCameraOption(o.scene.cameraFile); // likewise
    checkCalibrationOption(o.calibration);
    std::unique_ptr<GpuContext> ctx = createContext(o.device);
    RenderSettings settings = makeSettings(o.view, *ctx, o.knobs);
    settings.passStatistics = o.passStatistics;
    CameraSource camera;
    Scene scene = loadScene(o.scene, &camera);
    const std::optional<PathInput> pathInput = loadPathInput(o.path, scene, o.scene.seed);
    // After the input is checked: `measure` may take 40 s on lavapipe.
    const std::shared_ptr<const RunCalibration> calibration =
        loadRunCalibration(*ctx, o.calibration, o.passStatistics);
    const std::shared_ptr<EnergySource> energy = openDeviceEnergy(*ctx);
    ensureDirectory(o.out);
    SceneFeatures features = analyzeScene(scene, settings.msaa);
    std::fprintf(stderr, "triptych: %s, %zu triangles, %zu lights, %ux%u, %ux MSAA on %s\n",
                 scene.source.c_str(), scene.triangleCount(), scene.lights.size(), settings.width,
                 settings.height, settings.msaa, ctx->info.name.c_str());
    SceneGpu gpuScene(*ctx, scene);
    const nlohmann::json path = renderPath(o, pathInput, scene, gpuScene, *ctx, features, settings);
    RunOptions runOptions = progressRunOptions(o.pipeline, o.warmup, o.frames);
    runOptions.ceilings = ceilingsOf(*calibration);
    runOptions.energy = energy;
    Result<RunResult> result = runRenderer(*ctx, gpuScene, **entry, features, settings, runOptions);
    if (!result) throw UsageError(result.error());
    writeOutputs(o, scene, camera, *result, *ctx, settings, features, *calibration, *energy, path);
    for (const TimingStats& t : result->timings)
        std::fprintf(stderr, "  %-24s median %9.3f ms  (min %.3f, max %.3f, %u frames, %s)%s\n",
                     t.name.c_str(), t.medianMs, t.minMs, t.maxMs, t.frames,
                     ctx->info.name.c_str(), efficiencyNote(*result, t.name).c_str());
    if (energy->meter) std::fprintf(stderr, "  %s\n", energyLine(result->energy).c_str()); // else: the line below
    if (!calibration->available) std::fprintf(stderr, "triptych: efficiency left out: %s\n", calibration->why.c_str());
    noteEnergyLeftOut(*energy);
    std::fprintf(stderr, "triptych: wrote %s/%s.exr, .png, render.json, lights.json, camera.json\n",
                 o.out.c_str(), o.pipeline.c_str());
    return validationExit(ctx->validationMessages());
}

} // namespace

CommandRunner addRenderCommand(CLI::App& app) {
    auto o = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "Render one image with one pipeline");
    addSceneOptions(*cmd, o->scene);
    addViewOptions(*cmd, o->view);
    addDeviceOptions(*cmd, o->device);
    std::string names;
    for (const RendererEntry& e : registeredRenderers())
        names += "\n    " + e.name + ": " + e.description;
    cmd->add_option("--pipeline", o->pipeline, "Pipeline to render with:" + names)
        ->capture_default_str();
    cmd->add_option("--out", o->out, "Output directory (created if missing)")
        ->capture_default_str();
    cmd->add_option("--frames", o->frames, "Timed frames (median/min/max are over these)")
        ->capture_default_str();
    cmd->add_option("--warmup", o->warmup, "Untimed warm-up frames before the timed ones")
        ->capture_default_str();
    cmd->add_option(
           "--exposure", o->exposure,
           "Exposure in EV for the PNG (the EXR is linear): a number, or 'auto' (log-average "
           "luminance to 0.18)")
        ->capture_default_str();
    cmd->add_option("--exr-type", o->exrType, "EXR pixel type")
        ->check(CLI::IsMember({"half", "float"}))
        ->capture_default_str();
    cmd->add_option("--calibration", o->calibration, calibrationOptionHelp())->capture_default_str();
    addPassStatisticsOption(*cmd, o->passStatistics);
    addPathOptions(*cmd, o->path);
    addKnobOptions(*cmd, o->knobs.knobs);
    cmd->add_flag(
        "--debug", o->knobs.debug,
        "Also write the pipeline's debug images (lights-per-tile heat map, tile depth bounds, "
        "G-buffer channels, edge mask) as PIPELINE_debug_NAME.png");
    return [o, cmd]() { return cmd->parsed() ? run(*o) : -1; };
}

} // namespace tp::cli
