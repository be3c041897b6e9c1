// triptych sweep: every combination of light count, resolution, MSAA and pipeline knobs
// through the selected pipelines, the reference once per (light count, resolution, MSAA) for
// its image; a progress bar with the time left; a run that fails is recorded with its reason
// and the sweep goes on. Its runs: sweep_plan.h; files: sweep_output.h; meanings: docs/report.md.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>
#include <CLI/CLI.hpp>

#include "compare/cache/calibration_cache.h"
#include "compare/cache/reference_cache.h"
#include "compare/cache/scene_hash.h"
#include "compare/commands/commands.h"
#include "compare/commands/sweep.h"
#include "compare/commands/sweep_plan.h"
#include "compare/measure/path_run.h"
#include "compare/report/report_json.h"
#include "compare/report/run_json.h"
#include "compare/report/sweep_output.h"
#include "core/camera/camera_file.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/image/tonemap.h"
#include "core/reference/reference_renderer.h"
#include "core/runner/device_energy.h"
#include "core/renderer/view_settings.h"
#include "core/util/clock.h"
#include "core/util/files.h"

namespace tp::cli {
namespace {

using Clock = std::chrono::steady_clock;

struct Reference {
    std::optional<RunResult> run;
    std::optional<RunResult> center; // under MSAA: --reference-msaa center
    float ev = 0, peak = 1;
    FlipReference flip; // FLIP's share of the reference, prepared once (points into run)
};

SweepRow measureRun(const std::string& name, int lights, const RenderSettings& s,
                    const Result<RunResult>& result, const Reference& ref, const GpuContext& ctx) {
    SweepRow row;
    row.pipeline = name;
    row.lights = lights;
    row.s = s;
    if (!result) {
        row.status = "failed";
        row.error = result.error();
        return row;
    }
    const RunResult& r = result.value();
    row.frame = r.timings.front();
    row.run = runJson(r, ctx);
    row.efficiency = r.efficiency;
    row.energy = r.energy;
    row.bytes = row.run["memory"]["total_bytes"].get<uint64_t>();
    row.bytesPerPixel = row.run["memory"]["bytes_per_pixel"].get<double>();
    row.dropped = counterValue(r, "lights_dropped");
    if (ref.run && name != kReferenceRenderer) {
        MetricsOptions hdr;
        hdr.psnrPeak = ref.peak;
        row.hdr = computeError(r.hdr, ref.run->hdr, hdr);
        row.display =
            computeError(tonemapToDisplay(r.hdr, ref.ev), tonemapToDisplay(ref.run->hdr, ref.ev));
        row.flip = measureFlip(r.hdr, ref.flip, /*keepMaps=*/false);
        row.measured = true;
        row.exposureEv = ref.ev;
        row.hdrPsnrPeak = ref.peak;
        if (ref.center) {
            row.hdrCenter = computeError(r.hdr, ref.center->hdr, hdr);
            row.displayCenter = computeError(tonemapToDisplay(r.hdr, ref.ev),
                                             tonemapToDisplay(ref.center->hdr, ref.ev));
            row.measuredCenter = true;
        }
    }
    return row;
}

// Progress: runs done, time spent, and the time left from the average reference and
// pipeline run so far (a reference can cost a hundred pipeline runs).
struct Progress {
    size_t total = 0, references = 0, done = 0, referencesDone = 0;
    double referenceSeconds = 0, pipelineSeconds = 0;
    Clock::time_point start = Clock::now();

    // Under --shard: about 1/N of the runs and references are this process's.
    void shard(const Shard& s) {
        total = (total + s.count - 1 - s.index) / s.count;
        references = std::min(total, (references + s.count - 1) / s.count);
    }

    void report(const SweepRow& row, const std::string& resText) {
        ++done;
        bool isRef = row.pipeline == kReferenceRenderer;
        (isRef ? referenceSeconds : pipelineSeconds) += row.seconds;
        referencesDone += isRef;
        const size_t pipelinesDone = done - referencesDone, pipelinesTotal = total - references;
        const double perRef = referencesDone ? referenceSeconds / double(referencesDone) : 0.0;
        const double perRun = pipelinesDone ? pipelineSeconds / double(pipelinesDone) : perRef;
        const double left =
            double(references - referencesDone) * (referencesDone ? perRef : perRun) +
            double(pipelinesTotal - pipelinesDone) * perRun;
        const double spent = secondsSince(start);
        const int filled = int(30 * done / std::max<size_t>(1, total));
        std::fprintf(
            stderr, "[%s%s] %zu/%zu %s %d lights %s %ux: %s (%.1f s), %.0f s spent, ~%.0f s left\n",
            std::string(size_t(filled), '#').c_str(), std::string(size_t(30 - filled), '.').c_str(),
            done, total, row.pipeline.c_str(), row.lights, resText.c_str(), row.s.msaa,
            row.status == "ok" ? "ok" : ("FAILED: " + row.error).c_str(), row.seconds, spent, left);
    }
};

// The reference's frames (timed, no warm-up, with progress) or a pipeline's.
RunOptions sweepRunOptions(const SweepOptions& o, bool reference, std::shared_ptr<const CeilingRates> ceilings,
                           std::shared_ptr<EnergySource> energy) {
    RunOptions ro = reference ? progressRunOptions(kReferenceRenderer, 0, o.referenceFrames) : RunOptions{};
    if (!reference) {
        ro.warmupFrames = uint32_t(o.warmup);
        ro.timedFrames = uint32_t(o.frames);
    }
    ro.ceilings = std::move(ceilings);
    ro.energy = std::move(energy);
    return ro;
}

// A run; the reference's through the reference cache (`cache` says how it went).
Result<RunResult> runOne(GpuContext& ctx, SceneGpu& scene, const std::string& name,
                         const SceneFeatures& features, const RenderSettings& s,
                         const RunOptions& ro, const SweepOptions& o, ReferenceCacheUse& cache) {
    if (name == kReferenceRenderer)
        return runReferenceCached(ctx, scene, features, s, ro,
                                  referenceCacheDir(o.referenceCache, o.noReferenceCache), cache);
    return tryRunRenderer(ctx, scene, **findRenderer(name), features, s, ro);
}

// Under MSAA (unless --no-center-reference): the reference once more with --reference-msaa
// center, the second error's ground truth; its time is inside the reference row's seconds.
std::optional<RunResult> centerReference(const SweepOptions& o, GpuContext& ctx, SceneGpu& scene,
                                         const SceneFeatures& features, RenderSettings s,
                                         const RunOptions& ro) {
    if (s.msaa == 1 || !o.centerReference) return std::nullopt;
    s.set("reference-msaa", "center");
    ReferenceCacheUse cache;
    Result<RunResult> r = runOne(ctx, scene, kReferenceRenderer, features, s, ro, o, cache);
    if (!r) return std::nullopt;
    return std::move(*r);
}

struct View {
    RenderSettings settings;
    std::string text;
};

// Everything but the runs: enough to repeat the sweep and to know what it swept.
nlohmann::json sweepHeader(const SweepOptions& o, const Scene& scene, const CameraSource& camera,
                           const GpuContext& ctx) {
    nlohmann::json j;
    j["schema"] = "triptych.sweep/2";
    j["command_line"] = o.commandLine;
    j["command"] = shellJoin(o.commandLine);
    j["seed"] = o.scene.seed;
    j["scene"] = sceneJson(scene, analyzeScene(scene, 1));
    j["scene"].erase("lights"); // per run: it depends on the light count
    j["scene"]["path"] = o.scene.scene.empty() ? "builtin:courtyard" : o.scene.scene;
    FileHashes files =
        scene.source.rfind("builtin:", 0) == 0 ? FileHashes{} : hashSceneFiles(scene.source);
    j["scene"]["files_hash_fnv1a64"] =
        files.hash.empty() ? nlohmann::json(nullptr) : nlohmann::json(files.hash);
    j["scene"]["files_hashed"] = files.files;
    j["scene"]["content_hash_fnv1a64"] = hashSceneContent(scene);
    j["scene"]["camera_hash_fnv1a64"] = hashCamera(scene.camera);
    j["camera"] = cameraToJson(scene.camera); // a camera file, as in report.json
    j["camera_source"] = cameraSourceJson(camera);
    j["device"] = deviceJson(ctx);
    j["axes"] = {{"lights", o.lights},
                 {"res", o.res},
                 {"msaa", o.msaa},
                 {"light_types", o.scene.lightTypes}};
    for (const KnobReaders& k : allKnobs())
        j["axes"][k.knob.key()] = k.knob.valueIn(o.knobs);
    j["frames"] = o.frames;
    j["warmup"] = o.warmup;
    j["reference_frames"] = o.referenceFrames;
    j["pass_statistics"] = o.passStatistics ? "on" : "off";
    j["flip"] = flipConditionsJson(o.flipDistance);
    j["files"] = {"sweep.csv", "sweep.json", "sweep.html"};
    return j;
}

} // namespace

std::string sweepId(nlohmann::json header) {
    const std::string device = header["device"].value("name", "");
    for (const char* k : {"command", "command_line", "device", "validation_messages",
                          "sweep_id_fnv1a64", "merged_from", "calibration", "energy_source"})
        header.erase(k);
    header["shard"].erase("index");
    Fnv1a64 h;
    h.text(device);
    h.text(header.dump());
    return h.hex();
}

namespace {

void writeOutputs(const SweepOptions& o, const std::vector<SweepRow>& rows,
                  const nlohmann::json& header, const std::string& device) {
    Status s = writeTextFile(o.out + "/sweep.html",
                             sweepHtml(rows, device, shellJoin(o.commandLine)));
    if (s) s = writeTextFile(o.out + "/sweep.json", sweepJson(header, rows).dump(1) + "\n");
    if (s)
        s = writeTextFile(o.out + "/sweep.csv",
                          sweepCsv(rows, device)); // last: marks the sweep complete
    if (!s) throw UsageError(s.error());
}

// The reference run of one view and light count and what every row is measured against with
// it: exposure, peak, FLIP's share, the centre reference. Filled in place (flip points into run).
void setReference(Reference& ref, const RunResult& run, const SweepOptions& o, GpuContext& ctx,
                  SceneGpu& scene, const SceneFeatures& features, const RenderSettings& s,
                  const RunOptions& ro) {
    ref.run = run;
    ref.ev = autoExposureEv(ref.run->hdr);
    ref.peak = brightestFiniteChannel(ref.run->hdr);
    ref.flip = prepareFlipReference(ref.run->hdr, ref.ev, o.flipDistance);
    // Already at --reference-msaa center: that run is the centre reference.
    const auto mode = s.knobs.find("reference-msaa");
    ref.center =
        mode != s.knobs.end() && mode->second == "center" && s.msaa > 1 && o.centerReference
            ? ref.run
            : centerReference(o, ctx, scene, features, s, ro);
}

// One (light count, view) of the sweep: the reference, then every pipeline's knob
// combinations, each run numbered in the whole sweep's order. Under --shard a run is made when
// the shard owns its number, and the reference whenever the shard owns any run of the group
// (its rows are measured against it; from the cache when another shard stored it first).
struct GroupRunner {
    const SweepOptions& o;
    GpuContext& ctx;
    const std::vector<std::string>& names;
    Shard shard;
    Progress& progress;
    std::vector<SweepRow>& rows;
    std::shared_ptr<const CeilingRates> ceilings; // null: no calibration
    std::shared_ptr<EnergySource> energy;         // the device's energy counter, or why none
    size_t index = 0; // the next run's number

    // --camera-path: a pipeline row's timing pass over the path (compare/measure/path_run.h), then the
    // scene back at the path's first view for the next run.
    void runPath(Scene& scene, SceneGpu& gpuScene, const SceneFeatures& features,
                 const PathInput& path, SweepRow& row) {
        if (row.pipeline == kReferenceRenderer || row.status != "ok") return;
        PathRunSetup setup{ctx, scene, gpuScene, features, row.s, {row.pipeline}, o.warmup, o.frames};
        PathSeries series = timePath(setup, path, row.pipeline);
        applyPathView(scene, gpuScene, path, 0);
        row.path = seriesJson(series);
        row.path["views"] = path.views.size();
        if (series.error.empty()) return;
        row.status = "failed";
        row.error = "path: " + series.error;
    }

    void run(Scene& scene, SceneGpu& gpuScene, int lights, const std::string& lightsHash,
             const View& view, const std::optional<PathInput>& path) {
        std::vector<std::pair<std::string, RenderSettings>> runs;
        for (const std::string& name : names)
            for (const RenderSettings& s : knobCombos(name, o, view.settings))
                runs.push_back({name, s});
        bool any = false;
        for (size_t k = 0; k < runs.size(); ++k)
            any = any || shard.owns(index + k);
        const SceneFeatures features = analyzeScene(gpuScene.scene(), view.settings.msaa);
        Reference ref;
        for (size_t k = 0; k < runs.size(); ++k, ++index) {
            const auto& [name, s] = runs[k];
            const bool isRef = name == kReferenceRenderer, owned = shard.owns(index);
            if (!any || (!owned && !isRef)) continue;
            const RunOptions ro = sweepRunOptions(o, isRef, ceilings, energy);
            auto start = Clock::now();
            ReferenceCacheUse cache;
            Result<RunResult> result = runOne(ctx, gpuScene, name, features, s, ro, o, cache);
            if (isRef && result) setReference(ref, result.value(), o, ctx, gpuScene, features, s, ro);
            if (!owned) continue; // another shard's row: its figures are that shard's
            rows.push_back(measureRun(name, lights, s, result, ref, ctx));
            SweepRow& row = rows.back();
            if (path) runPath(scene, gpuScene, features, *path, row);
            row.seconds = secondsSince(start);
            row.lightsHash = lightsHash;
            row.runIndex = index;
            if (isRef) row.referenceCache = referenceCacheJson(cache);
            progress.report(row, view.text);
        }
    }
};

} // namespace

int runSweep(const SweepOptions& o) {
    checkFrameCounts(o.frames, o.warmup);
    if (o.referenceFrames < 0 || o.referenceFrames > 1000)
        throw UsageError("--reference-frames must be between 0 and 1000");
    checkFlipDistance(o.flipDistance);
    checkKnobLists(o);
    std::vector<std::string> names = selectPipelines(o.pipelines);
    if (o.referenceFrames > 0) names.insert(names.begin(), kReferenceRenderer);
    if (!o.scene.cameraFile.empty())
        readCameraOption(o.scene.cameraFile); // refuse before any GPU work
    loadPathInput(o.path, Scene{}, o.scene.seed); // likewise (read again per scene: its lights)
    std::vector<int> lightCounts;
    for (const std::string& s : splitList(o.lights, "--lights"))
        lightCounts.push_back(toInt(s, "--lights"));
    checkCalibrationOption(o.calibration);
    std::unique_ptr<GpuContext> ctx = createContext(o.device);
    RenderSettings base;
    base.passStatistics = o.passStatistics;
    std::vector<View> views; // validated up front: bad input fails before any run
    for (const std::string& r : splitList(o.res, "--res"))
        for (const std::string& m : splitList(o.msaa, "--msaa"))
            views.push_back({makeSettings(ViewOptions{r, toInt(m, "--msaa")}, *ctx, base), r});
    Progress progress;
    for (const View& view : views)
        for (const std::string& n : names)
            progress.total += knobCombos(n, o, view.settings).size();
    progress.total *= lightCounts.size();
    progress.references = o.referenceFrames > 0 ? lightCounts.size() * views.size() : 0;
    const Shard shard = parseShard(o.shard);
    // After the input is checked (a scene is checked when loaded): `measure` may take 40 s.
    const std::shared_ptr<const RunCalibration> calibration =
        loadRunCalibration(*ctx, o.calibration, o.passStatistics);
    const std::shared_ptr<EnergySource> energy = openDeviceEnergy(*ctx);
    progress.shard(shard);
    ensureDirectory(o.out);
    for (const char* f : {"sweep.csv", "sweep.json", "sweep.html"})
        std::remove((o.out + "/" + f).c_str());

    std::vector<SweepRow> rows;
    nlohmann::json header;
    GroupRunner group{o, *ctx, names, shard, progress, rows, ceilingsOf(*calibration), energy};
    for (int lights : lightCounts) {
        SceneOptions so = o.scene;
        so.lightCount = lights;
        CameraSource camera;
        Scene scene = loadScene(so, &camera);
        const std::optional<PathInput> path = loadPathInput(o.path, scene, o.scene.seed);
        if (path) scene.camera = path->views.front(); // every row's single view: the first
        if (header.is_null()) header = sweepHeader(o, scene, camera, *ctx);
        if (path) header["path"] = {{"source", path->source}, {"views", path->views.size()},
                                    {"light_motion", path->lightMotion}};
        SceneGpu gpuScene(*ctx, scene);
        for (const View& view : views)
            group.run(scene, gpuScene, lights, hashLights(scene.lights), view, path);
    }
    header["shard"] = {{"index", shard.index}, {"count", shard.count}, {"runs", group.index}};
    header["sweep_id_fnv1a64"] = sweepId(header);
    header["calibration"] = calibrationUseJson(*calibration); // per machine: outside the id
    header["energy_source"] = energySourceJson(*energy);      // likewise
    const std::vector<std::string> validation = ctx->validationMessages();
    header["validation_messages"] = validation;
    writeOutputs(o, rows, header, ctx->info.name);
    size_t failed = size_t(std::count_if(rows.begin(), rows.end(),
                                         [](const SweepRow& r) { return r.status != "ok"; }));
    std::printf("triptych sweep: %zu runs (%zu failed) on %s; wrote %s/sweep.csv, sweep.json and "
                "sweep.html\n",
                rows.size(), failed, ctx->info.name.c_str(), o.out.c_str());
    if (!calibration->available) // after the run: an error before it stays one line
        std::fprintf(stderr, "triptych: efficiency left out: %s\n", calibration->why.c_str());
    noteEnergyLeftOut(*energy);
    if (int code = validationExit(validation)) return code;
    return failed == 0 ? 0 : 5;
}

CommandRunner addSweepCommand(CLI::App& app, std::vector<std::string> commandLine) {
    auto o = std::make_shared<SweepOptions>();
    o->commandLine = std::move(commandLine);
    CLI::App* cmd = app.add_subcommand(
        "sweep",
        "Every combination of lights, resolution, MSAA and pipeline knobs through the pipelines, "
        "the reference once per light count/resolution/MSAA: sweep.csv, sweep.json and "
        "sweep.html. Exit 0 ok, 2 bad input, 3 validation messages, 4 Vulkan failure, 5 a run "
        "failed");
    addSweepOptions(*cmd, *o);
    return [o, cmd]() {
        if (!cmd->parsed()) return -1;
        checkKnobs(o->knobs, true); // the single values; runSweep checks the lists
        return runSweep(*o);
    };
}

} // namespace tp::cli
