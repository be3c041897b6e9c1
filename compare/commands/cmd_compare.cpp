// triptych compare: the reference and each selected pipeline on one SceneGpu (same scene,
// camera and lights), one exposure for every PNG (auto from the reference), signed
// difference EXRs and heat maps on one shared scale, metrics against the reference and
// between pipelines, then report.html and, last, report.json: a directory without
// report.json is an unfinished run. The measurements and their maps: compare_measure.h.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <future>
#include <CLI/CLI.hpp>

#include "compare/cache/calibration_cache.h"
#include "compare/cache/reference_cache.h"
#include "compare/commands/commands.h"
#include "compare/commands/compare.h"
#include "compare/commands/compare_measure.h"
#include "compare/measure/path_run.h"
#include "compare/report/compare_summary.h"
#include "compare/report/report_html.h"
#include "compare/report/report_json.h"
#include "compare/report/run_json.h"
#include "core/camera/camera_file.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/image/difference.h"
#include "core/image/flip.h"
#include "core/image/image_io.h"
#include "core/image/tonemap.h"
#include "core/reference/reference_renderer.h"
#include "core/runner/device_energy.h"
#include "core/util/files.h"

namespace tp::cli {
namespace {

void check(const Status& s) {
    if (!s) throw UsageError(s.error());
}

// A previous run's report must not survive next to this run's partial output.
void removeStaleOutputs(const std::string& out, const std::vector<std::string>& names) {
    std::vector<std::string> files = {
        "report.json",   "report.html",   "lights.json",          "camera.json",
        "reference.exr", "reference.png", "reference_center.exr", "reference_center.png"};
    for (const std::string& n : names)
        for (const char* suffix : {".exr", ".png", "_diff.exr", "_diff.png", "_flip.exr",
                                   "_flip.png", "_flip_ldr.exr", "_flip_ldr.png"})
            files.push_back(n + suffix);
    for (size_t i = 0; i < names.size(); ++i)
        for (size_t k = i + 1; k < names.size(); ++k)
            for (const char* suffix : {".exr", ".png"})
                files.push_back(pairDiffStem(names[i], names[k]) + suffix);
    for (const std::string& f : files) {
        std::error_code ec;
        std::filesystem::remove(out + "/" + f, ec);
    }
}

// Each run's images are encoded (EXR and PNG) and measured against the reference (metrics,
// FLIP), CPU work, while the next pipeline is set up and warms up: on a CPU device that leaves
// part of the cores idle (docs/visbuffer.md, "compare on lavapipe"). It is waited for before
// that pipeline's timed frames, whose time on a CPU device is CPU time that a thread beside
// them would take. wait() only waits (inside a run, where a failure is not the renderer's);
// join() also rethrows the first failure (a file that cannot be written).
class BackgroundWork {
  public:
    ~BackgroundWork() { wait(); }
    void wait() {
        for (std::future<void>& f : pending_)
            if (f.valid()) f.wait();
    }
    void add(std::function<void()> work) {
        pending_.push_back(std::async(std::launch::async, std::move(work)));
    }
    void join() {
        for (std::future<void>& f : pending_)
            f.get();
        pending_.clear();
    }

  private:
    std::vector<std::future<void>> pending_;
};

// Runs one renderer; a renderer that cannot be built, or a Vulkan failure inside it, becomes
// a failed outcome so the other pipelines still run.
// `background`: waited for before the first timed frame (BackgroundWork).
PipelineOutcome renderOne(GpuContext& ctx, SceneGpu& scene, const std::string& name,
                          const CompareRecord& r, const CompareOptions& o, const std::string& label,
                          BackgroundWork* background = nullptr) {
    PipelineOutcome p;
    p.name = name;
    const RendererEntry* entry = *findRenderer(name);
    auto start = std::chrono::steady_clock::now();
    std::fprintf(stderr, "triptych: %s %s ...\n", label.c_str(), name.c_str());
    RunOptions ro = progressRunOptions(name, o.warmup, o.frames);
    if (background && o.warmup == 0) background->wait();
    if (background && o.warmup > 0)
        ro.onFrame = [background, timed = uint32_t(o.frames), print = ro.onFrame](
                         uint32_t f, uint32_t total, double ms) {
            print(f, total, ms);
            if (f + 1 + timed == total) background->wait(); // the last warm-up frame
        };
    if (r.calibration) ro.ceilings = ceilingsOf(*r.calibration);
    ro.energy = r.energy;
    Result<RunResult> result =
        name == kReferenceRenderer
            ? runReferenceCached(ctx, scene, r.features, r.settings, ro,
                                 referenceCacheDir(o.referenceCache, o.noReferenceCache),
                                 p.cache)
            : tryRunRenderer(ctx, scene, *entry, r.features, r.settings, ro);
    if (result)
        p.run = std::move(*result);
    else
        p.error = result.error();
    std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    if (p.run && p.cache.reused)
        std::fprintf(stderr, "triptych: %s %s reused from the cache (%s, rendered %s) in %.1f s\n",
                     label.c_str(), name.c_str(), p.cache.entry.c_str(),
                     p.cache.renderedAt.c_str(), took.count());
    else if (p.run)
        std::fprintf(stderr, "triptych: %s %s done in %.1f s\n", label.c_str(), name.c_str(),
                     took.count());
    else
        std::fprintf(stderr, "triptych: %s %s FAILED: %s\n", label.c_str(), name.c_str(),
                     p.error.c_str());
    return p;
}

void writeImages(const std::string& out, PipelineOutcome& p, float ev) {
    check(writeExr(out + "/" + p.name + ".exr", p.run->hdr, ExrPixelType::Float));
    check(writePng(out + "/" + p.name + ".png", tonemapToDisplay(p.run->hdr, ev)));
    p.files = {p.name + ".exr", p.name + ".png"};
}

// Each run's images written and its measurements against the reference taken beside the next
// pipeline's setup and warm-up (BackgroundWork).
void renderPipelines(CompareRecord& r, const CompareOptions& o, GpuContext& ctx, SceneGpu& gpuScene,
                     const std::vector<std::string>& names, BackgroundWork& background,
                     ReferenceMeasures& measures) {
    r.pipelines.reserve(names.size()); // each outcome stays where its write finds it
    for (size_t i = 0; i < names.size(); ++i) {
        std::string label =
            "[" + std::to_string(i + 2) + "/" + std::to_string(names.size() + 1) + "]";
        r.pipelines.push_back(renderOne(ctx, gpuScene, names[i], r, o, label, &background));
        background.join(); // done before the run's timed frames: a failed write ends the run here
        PipelineOutcome& p = r.pipelines.back();
        if (!p.run) continue;
        warnDropped(p);
        background.add([&out = o.out, &p, ev = r.exposureEv, &measures, i] {
            writeImages(out, p, ev);
            measures.measure(p, i);
        });
    }
}

// A second reference: the reference rendered once more with one of its knobs changed, and
// every pipeline measured against it too (the two errors split what a pipeline gets wrong).
struct SecondReference {
    const char* knob;  // the reference's knob and the value the second one takes
    const char* value;
    const char* label; // progress line
    const char* name;  // its images and report name
    PipelineOutcome CompareRecord::*outcome;
    std::optional<ErrorReport> PipelineOutcome::*hdr;
    std::optional<ErrorReport> PipelineOutcome::*display;
};

void measureAgainst(CompareRecord& r, const CompareOptions& o, GpuContext& ctx, SceneGpu& gpuScene,
                    const SecondReference& s) {
    CompareRecord c; // what renderOne reads, with the second reference's knob
    c.features = r.features;
    c.settings = r.settings;
    c.calibration = r.calibration;
    c.energy = r.energy;
    c.settings.set(s.knob, s.value);
    PipelineOutcome& second = r.*s.outcome;
    // A reference already run with that value is the second reference: not again.
    const auto mode = r.settings.knobs.find(s.knob);
    const bool already = mode != r.settings.knobs.end() && mode->second == s.value;
    second = already ? r.reference : renderOne(ctx, gpuScene, kReferenceRenderer, c, o, s.label);
    second.name = s.name;
    if (!second.run) return;
    writeImages(o.out, second, r.exposureEv);
    MetricsOptions hdr;
    hdr.psnrPeak = r.hdrPsnrPeak;
    const ImageRGBA secondDisplay = tonemapToDisplay(second.run->hdr, r.exposureEv);
    second.hdr = computeError(second.run->hdr, r.reference.run->hdr, hdr);
    second.display =
        computeError(secondDisplay, tonemapToDisplay(r.reference.run->hdr, r.exposureEv));
    for (PipelineOutcome& p : r.pipelines) {
        if (!p.run) continue;
        p.*s.hdr = computeError(p.run->hdr, second.run->hdr, hdr);
        p.*s.display = computeError(tonemapToDisplay(p.run->hdr, r.exposureEv), secondDisplay);
    }
}

// Under MSAA, the second error: the reference rendered once more with --reference-msaa center
// (every sample shaded at the pixel centre). The error against the supersampled reference is
// the total; against this one, the method alone.
void measureAgainstCenterReference(CompareRecord& r, const CompareOptions& o, GpuContext& ctx, SceneGpu& gpuScene) {
    if (r.settings.msaa == 1 || !o.centerReference) return;
    measureAgainst(r, o, ctx, gpuScene,
                   {"reference-msaa", "center", "[center reference]", "reference_center",
                    &CompareRecord::centerReference, &PipelineOutcome::hdrVsCenter,
                    &PipelineOutcome::displayVsCenter});
}

// With --shadows, the reference casts shadow rays (exact visibility); the second one samples the
// very shadow maps the pipelines render (--reference-shadows maps). Against the first, a
// pipeline's error is the total; against the second, its lighting architecture's part alone.
void measureAgainstShadowMapReference(CompareRecord& r, const CompareOptions& o, GpuContext& ctx,
                                      SceneGpu& gpuScene) {
    if (!r.settings.shadows.enabled() || r.shadowPlan.empty()) return; // no light shadowed here
    measureAgainst(r, o, ctx, gpuScene,
                   {"reference-shadows", "maps", "[shadow-map reference]", "reference_shadow_maps",
                    &CompareRecord::shadowMapReference, &PipelineOutcome::hdrVsShadowMaps,
                    &PipelineOutcome::displayVsShadowMaps});
}

// The path first (compare/measure/path_run.h); the rest of the run is the full report at its worst
// view, so the scene's camera and lights are left there and its hashes follow.
void runComparePath(CompareRecord& r, const CompareOptions& o, GpuContext& ctx, Scene& scene, SceneGpu& gpuScene,
                    const std::vector<std::string>& names, const PathInput& path) {
    PathRunSetup setup{ctx, scene, gpuScene, r.features, r.settings, names, o.warmup, o.frames,
                       o.exposure};
    PathRecord rec = runPath(setup, path);
    applyPathView(scene, gpuScene, path, rec.worstView);
    r.contentHash = hashSceneContent(scene);
    r.lightsHash = hashLights(scene.lights);
    r.path = pathJson(rec);
    std::fprintf(stderr, "triptych: path done; the full report follows at its worst view, %u\n",
                 rec.worstView);
}

// What report.json records of the options (the writers never see the options themselves).
CompareRequest requestOf(const CompareOptions& o) {
    return {o.commandLine, o.scene.seed,   o.scene.scene, o.scene.lightTypes, o.scene.lightCount,
            o.frames,      o.warmup,       o.exposure,    o.flipDistance,     o.centerReference};
}

} // namespace

int runCompare(const CompareOptions& o) {
    checkFrameCounts(o.frames, o.warmup);
    checkFlipDistance(o.flipDistance);
    std::vector<std::string> names = selectPipelines(o.pipelines);
    if (o.exposure != "auto") parseExposure(o.exposure, ImageRGBA{}); // refuse before rendering
    if (!o.scene.cameraFile.empty()) readCameraOption(o.scene.cameraFile); // likewise
    checkCalibrationOption(o.calibration);
    std::unique_ptr<GpuContext> ctx = createContext(o.device);
    CompareRecord r;
    r.request = requestOf(o);
    r.ctx = ctx.get();
    r.settings = makeSettings(o.view, *ctx, o.knobs);
    r.settings.passStatistics = o.passStatistics;
    r.energy = openDeviceEnergy(*ctx);
    Scene scene = loadScene(o.scene, &r.cameraSource);
    r.scene = &scene;
    r.features = analyzeScene(scene, r.settings.msaa);
    if (scene.source.rfind("builtin:", 0) != 0) {
        r.sceneHash = hashFile(scene.source);
        r.sceneFiles = hashSceneFiles(scene.source);
    }
    r.contentHash = hashSceneContent(scene);
    r.lightsHash = hashLights(scene.lights);
    const std::optional<PathInput> path = loadPathInput(o.path, scene, o.scene.seed);
    r.calibration = loadRunCalibration(*ctx, o.calibration, o.passStatistics); // after the input is checked
    ensureDirectory(o.out);
    removeStaleOutputs(o.out, names);
    std::fprintf(
        stderr,
        "triptych: compare %s, %zu triangles, %zu lights, %ux%u, %ux MSAA, %d+%d frames on %s\n",
        scene.source.c_str(), scene.triangleCount(), scene.lights.size(), r.settings.width,
        r.settings.height, r.settings.msaa, o.warmup, o.frames, ctx->info.name.c_str());

    SceneGpu gpuScene(*ctx, scene);
    r.sharedMemory = ctx->ledger.entriesOf("scene");
    if (path) runComparePath(r, o, *ctx, scene, gpuScene, names, *path);
    r.reference = renderOne(*ctx, gpuScene, kReferenceRenderer, r, o,
                            "[1/" + std::to_string(names.size() + 1) + "]");
    if (!r.reference.run)
        throw UsageError("the reference failed, nothing to compare against: " + r.reference.error);
    r.exposureEv = parseExposure(o.exposure, r.reference.run->hdr);
    r.hdrPsnrPeak = brightestFiniteChannel(r.reference.run->hdr);
    BackgroundWork background;
    background.add([&] { writeImages(o.out, r.reference, r.exposureEv); });
    check(writeLightsFile(o.out + "/lights.json", scene.lights));
    check(writeCameraFile(o.out + "/camera.json", scene.camera)); // ready for --camera

    ReferenceMeasures measures(r, names.size());
    renderPipelines(r, o, *ctx, gpuScene, names, background, measures);
    background.join();
    r.shadowPlan = gpuScene.shadowPlan(); // set up by the runs (a cached reference sets up nothing)
    // Again after the runs: a pipeline that culls meshlets had the scene build them
    // (SceneGpu::buildMeshlets, docs/geometry.md), and they are the scene's.
    r.sharedMemory = ctx->ledger.entriesOf("scene");
    measures.write(r, o.out);
    measurePairs(r, o.out);
    measureAgainstCenterReference(r, o, *ctx, gpuScene);
    measureAgainstShadowMapReference(r, o, *ctx, gpuScene);
    r.validationMessages = ctx->validationMessages();

    nlohmann::json report = reportJson(r);
    Result<std::string> html = reportHtml(report, o.out);
    if (!html) throw UsageError(html.error());
    check(writeTextFile(o.out + "/report.html", *html));
    check(writeTextFile(o.out + "/report.json",
                        report.dump(2) + "\n")); // last: marks the run complete
    printSummary(r);
    std::fprintf(stderr, "triptych: wrote %s/report.html, report.json and the images\n",
                 o.out.c_str());
    if (!r.calibration->available) // after the run: an error before it stays one line
        std::fprintf(stderr, "triptych: efficiency left out: %s\n", r.calibration->why.c_str());
    noteEnergyLeftOut(*r.energy);

    if (int code = validationExit(r.validationMessages)) return code;
    return report["status"] == "ok" ? 0 : 5;
}

CommandRunner addCompareCommand(CLI::App& app, std::vector<std::string> commandLine) {
    auto o = std::make_shared<CompareOptions>();
    o->commandLine = std::move(commandLine);
    CLI::App* cmd = app.add_subcommand(
        "compare",
        "Render the scene with the reference and each pipeline (same camera and lights); write "
        "images, difference maps against the reference and between pipelines, report.json and "
        "report.html. Exit 0 ok, 2 bad input, 3 validation messages, 4 Vulkan failure, 5 a "
        "pipeline failed");
    addSceneOptions(*cmd, o->scene);
    addViewOptions(*cmd, o->view);
    addDeviceOptions(*cmd, o->device);
    cmd->add_option("--pipelines", o->pipelines,
                    "Comma-separated pipelines to compare with the reference (default: all: " +
                        defaultPipelineList() + ")");
    cmd->add_option("--out", o->out,
                    "Output directory (created if missing) for the EXR/PNG images, difference "
                    "maps, lights.json, "
                    "report.json and report.html; this run's files there are replaced")
        ->capture_default_str();
    cmd->add_option("--calibration", o->calibration, calibrationOptionHelp())->capture_default_str();
    addPassStatisticsOption(*cmd, o->passStatistics);
    cmd->add_option("--frames", o->frames,
                    "Timed frames per pipeline (median/min/max are over these)")
        ->capture_default_str();
    cmd->add_option("--warmup", o->warmup, "Untimed warm-up frames before the timed ones")
        ->capture_default_str();
    cmd->add_option("--exposure", o->exposure,
                    "Exposure in EV of every PNG (EXRs are linear): a number, or 'auto' (from the "
                    "reference)")
        ->capture_default_str();
    cmd->add_flag("--no-center-reference{false}", o->centerReference,
                  "Under MSAA, skip the second reference (--reference-msaa center, one more "
                  "reference render) and "
                  "the error against it");
    addFlipDistanceOption(*cmd, o->flipDistance);
    addReferenceCacheOptions(*cmd, o->referenceCache, o->noReferenceCache);
    addPathOptions(*cmd, o->path);
    addKnobOptions(*cmd, o->knobs.knobs);
    return [o, cmd]() {
        if (!cmd->parsed()) return -1;
        checkKnobs(
            o->knobs.knobs); // runCompare itself records a bad knob as that pipeline's failure
        return runCompare(*o);
    };
}

} // namespace tp::cli
