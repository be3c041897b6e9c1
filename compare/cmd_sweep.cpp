// triptych sweep: every combination of light count, resolution, MSAA and pipeline knobs
// through the selected pipelines, the reference once per (light set, resolution, MSAA);
// one sweep.csv row per run (failed runs included, with their reason) and sweep.html with
// time against light count, memory against MSAA, and error against time with the Pareto front.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "compare/cli_common.h"
#include "compare/commands.h"
#include "compare/report_html.h"
#include "compare/svg_plot.h"
#include "core/gpu/vk_check.h"
#include "core/image/metrics.h"
#include "core/image/tonemap.h"
#include "core/render/scene_gpu.h"
#include "core/util/files.h"

namespace tp::cli {
namespace {

struct SweepOptions {
    SceneOptions scene;
    DeviceOptions device;
    std::string lights = "16,64,256", res = "320x180", msaa = "1", tile = "16", lightLists = "compact",
                gbuffer = "compact", accum = "fp32", pipelines, out = "sweep";
    int frames = 2, warmup = 1;
};

std::vector<std::string> splitList(const std::string& text, const char* option) {
    std::vector<std::string> items;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ','))
        if (!item.empty()) items.push_back(item);
    if (items.empty()) throw UsageError(std::string(option) + " '" + text + "': empty list");
    return items;
}

int toInt(const std::string& s, const char* option) {
    char* end = nullptr;
    long v = std::strtol(s.c_str(), &end, 10);
    if (end == s.c_str() || *end || v < 0 || v > 1000000) throw UsageError(std::string(option) + ": bad value '" + s + "'");
    return int(v);
}

// Which knobs change which pipeline: a pipeline is run once per value of the knobs it reads
// and with the first value of the others, so the sweep does not repeat identical runs.
bool reads(const std::string& pipeline, const std::string& knob) {
    static const std::map<std::string, std::vector<std::string>> table = {
        {"tile", {"forwardplus", "deferred"}},
        {"light_lists", {"forwardplus"}},
        {"gbuffer", {"deferred"}},
        {"accum", {"multipass_forward"}}};
    const auto& users = table.at(knob);
    return std::find(users.begin(), users.end(), pipeline) != users.end();
}

struct Row {
    std::string pipeline, status = "ok", error;
    int lights = 0;
    RenderSettings s;
    double frameMs = 0, minMs = 0, maxMs = 0, bytesPerPixel = 0, rmse = 0, psnrTm = 0, maxAbs = 0, dropped = 0;
    uint64_t bytes = 0;
};

std::vector<RenderSettings> knobCombos(const std::string& pipeline, const SweepOptions& o, RenderSettings base) {
    std::vector<RenderSettings> combos = {base};
    auto expand = [&](const std::string& knob, const std::string& list, auto apply) {
        std::vector<std::string> values = splitList(list, ("--" + knob).c_str());
        if (!reads(pipeline, knob)) values.resize(1);
        std::vector<RenderSettings> next;
        for (const RenderSettings& c : combos)
            for (const std::string& v : values) {
                RenderSettings n = c;
                apply(n, v);
                next.push_back(n);
            }
        combos = next;
    };
    expand("tile", o.tile, [](RenderSettings& s, const std::string& v) { s.tileSize = uint32_t(toInt(v, "--tile")); });
    expand("light_lists", o.lightLists, [](RenderSettings& s, const std::string& v) { s.lightLists = v; });
    expand("gbuffer", o.gbuffer, [](RenderSettings& s, const std::string& v) { s.gbuffer = v; });
    expand("accum", o.accum, [](RenderSettings& s, const std::string& v) { s.accum = v; });
    return combos;
}

Row measureRun(const std::string& name, int lights, const RenderSettings& s, const Result<RunResult>& run,
               const RunResult* reference, float ev) {
    Row row;
    row.pipeline = name;
    row.lights = lights;
    row.s = s;
    if (!run) {
        row.status = "failed";
        row.error = run.error();
        return row;
    }
    const RunResult& r = run.value();
    row.frameMs = r.timings.front().medianMs;
    row.minMs = r.timings.front().minMs;
    row.maxMs = r.timings.front().maxMs;
    for (const LedgerEntry& e : r.memory) row.bytes += e.bytes;
    row.bytesPerPixel = double(row.bytes) / double(std::max<size_t>(1, r.hdr.pixelCount()));
    for (const auto& [k, v] : r.stats.counters)
        if (k == "lights_dropped") row.dropped = v;
    if (reference) {
        ErrorReport e = computeError(r.hdr, reference->hdr);
        row.rmse = e.rmse;
        row.maxAbs = e.maxAbs;
        row.psnrTm = computeError(tonemapToDisplay(r.hdr, ev), tonemapToDisplay(reference->hdr, ev)).psnr;
    }
    return row;
}

std::string csvField(std::string s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string csv(const std::vector<Row>& rows, const std::string& device) {
    std::string t = "pipeline,lights,width,height,msaa,tile,light_lists,gbuffer,accum,status,frame_median_ms,"
                    "frame_min_ms,frame_max_ms,memory_bytes,bytes_per_pixel,rmse_hdr,psnr_tonemapped,max_abs_hdr,"
                    "lights_dropped,device,error\n";
    for (const Row& r : rows) {
        char nums[512];
        std::snprintf(nums, sizeof nums, "%.6g,%.6g,%.6g,%llu,%.6g,%.6g,%.6g,%.6g,%.0f", r.frameMs, r.minMs, r.maxMs,
                      (unsigned long long)r.bytes, r.bytesPerPixel, r.rmse, r.psnrTm, r.maxAbs, r.dropped);
        t += csvField(r.pipeline) + "," + std::to_string(r.lights) + "," + std::to_string(r.s.width) + "," +
             std::to_string(r.s.height) + "," + std::to_string(r.s.msaa) + "," + std::to_string(r.s.tileSize) + "," +
             r.s.lightLists + "," + r.s.gbuffer + "," + r.s.accum + "," + r.status + "," + nums + "," +
             csvField(device) + "," + csvField(r.error) + "\n";
    }
    return t;
}

std::string sweepHtml(const std::vector<Row>& rows, const std::vector<std::string>& names, const std::string& device,
                      const std::string& command) {
    auto series = [&](const std::string& p) { return int(std::find(names.begin(), names.end(), p) - names.begin()); };
    std::vector<PlotPoint> time, memory, error;
    std::set<std::string> firstOfKind;
    for (const Row& r : rows) {
        if (r.status != "ok") continue;
        int si = series(r.pipeline);
        // Time against lights: the first resolution, MSAA and knob values only, one line per pipeline.
        if (r.s.width == rows.front().s.width && r.s.msaa == rows.front().s.msaa &&
            firstOfKind.insert(r.pipeline + "/" + std::to_string(r.lights)).second)
            time.push_back({"", double(r.lights), r.frameMs, si});
        memory.push_back({"", double(r.s.msaa), double(r.bytes), si});
        if (r.pipeline != "reference") error.push_back({"", r.frameMs, r.rmse, si});
    }
    // Pareto front: no other run is both faster and closer to the reference.
    for (PlotPoint& p : error) {
        p.ring = std::none_of(error.begin(), error.end(), [&](const PlotPoint& q) {
            return q.x <= p.x && q.y <= p.y && (q.x < p.x || q.y < p.y);
        });
    }
    std::string failed;
    for (const Row& r : rows)
        if (r.status != "ok") failed += "<li>" + escapeXml(r.pipeline + " (" + std::to_string(r.lights) + " lights): " + r.error) + "</li>";
    return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>triptych sweep</title><style>"
           "body{font-family:sans-serif;margin:16px 24px}h2{font-size:18px;border-bottom:1px solid #ccc}"
           "</style></head><body><h1>triptych sweep</h1><p>Device: <b>" + escapeXml(device) +
           "</b>. Command: <code>" + escapeXml(command) + "</code>. Every run is a row of sweep.csv.</p>" +
           (failed.empty() ? "" : "<h2>Failed runs</h2><ul>" + failed + "</ul>") +
           "<h2>Frame time against light count</h2>" +
           scatterLogLogSvg(time, "lights", "frame median ms", 720, 440, names) +
           "<h2>Memory against MSAA</h2>" + scatterLogLogSvg(memory, "MSAA samples", "pipeline bytes", 720, 440, names, false) +
           "<h2>Error against run time (circled: Pareto front)</h2>" +
           scatterLogLogSvg(error, "frame median ms", "RMSE vs reference (HDR)", 720, 440, names, false) + "</body></html>\n";
}

int run(SweepOptions& o, const std::vector<std::string>& commandLine) {
    checkFrameCounts(o.frames, o.warmup);
    std::vector<std::string> names = {"reference"};
    for (const RendererEntry& e : registeredRenderers())
        if (e.name != "reference" && (o.pipelines.empty() || ("," + o.pipelines + ",").find("," + e.name + ",") != std::string::npos))
            names.push_back(e.name);
    std::vector<int> lightCounts;
    for (const std::string& s : splitList(o.lights, "--lights")) lightCounts.push_back(toInt(s, "--lights"));
    std::vector<std::string> resolutions = splitList(o.res, "--res"), msaas = splitList(o.msaa, "--msaa");
    std::unique_ptr<GpuContext> ctx = createContext(o.device);
    std::vector<std::pair<RenderSettings, std::string>> views; // validated up front: bad input fails before any run
    for (const std::string& r : resolutions)
        for (const std::string& m : msaas) views.push_back({makeSettings(ViewOptions{r, toInt(m, "--msaa")}, *ctx), r});
    size_t total = 0;
    for (const std::string& n : names) total += knobCombos(n, o, {}).size();
    total *= lightCounts.size() * views.size();
    ensureDirectory(o.out);

    std::vector<Row> rows;
    auto start = std::chrono::steady_clock::now();
    for (int lights : lightCounts) {
        SceneOptions so = o.scene;
        so.lightCount = lights;
        Scene scene = loadScene(so);
        SceneGpu gpuScene(*ctx, scene);
        for (const auto& [view, resText] : views) {
            SceneFeatures features = analyzeScene(scene, view.msaa);
            std::optional<RunResult> reference;
            float ev = 0;
            for (const std::string& name : names)
                for (const RenderSettings& s : knobCombos(name, o, view)) {
                    Result<RunResult> result = Error{"not run"};
                    try {
                        RunOptions ro;
                        ro.warmupFrames = uint32_t(o.warmup);
                        ro.timedFrames = uint32_t(o.frames);
                        result = runRenderer(*ctx, gpuScene, **findRenderer(name), features, s, ro);
                    } catch (const GpuError& e) {
                        result = Error{std::string("Vulkan error: ") + e.what()};
                    }
                    if (name == "reference" && result) {
                        reference = result.value();
                        ev = autoExposureEv(reference->hdr);
                    }
                    rows.push_back(measureRun(name, lights, s, result, reference ? &*reference : nullptr, ev));
                    std::chrono::duration<double> spent = std::chrono::steady_clock::now() - start;
                    double left = spent.count() / double(rows.size()) * double(total - rows.size());
                    int filled = int(30 * rows.size() / total);
                    std::fprintf(stderr, "[%s%s] %zu/%zu %s %d lights %s %ux: %s, %.0f s spent, ~%.0f s left\n",
                                 std::string(size_t(filled), '#').c_str(), std::string(size_t(30 - filled), '.').c_str(),
                                 rows.size(), total, name.c_str(), lights, resText.c_str(), s.msaa,
                                 rows.back().status == "ok" ? "ok" : ("FAILED: " + rows.back().error).c_str(),
                                 spent.count(), left);
                }
        }
    }
    std::string command;
    for (const std::string& a : commandLine) command += (command.empty() ? "" : " ") + a;
    Status s = writeTextFile(o.out + "/sweep.html", sweepHtml(rows, names, ctx->info.name, command));
    if (s) s = writeTextFile(o.out + "/sweep.csv", csv(rows, ctx->info.name)); // last: marks the sweep complete
    if (!s) throw UsageError(s.error());
    size_t failed = size_t(std::count_if(rows.begin(), rows.end(), [](const Row& r) { return r.status != "ok"; }));
    std::printf("triptych sweep: %zu runs (%zu failed) on %s; wrote %s/sweep.csv and sweep.html\n", rows.size(), failed,
                ctx->info.name.c_str(), o.out.c_str());
    return failed == 0 ? 0 : 5;
}

} // namespace

CommandRunner addSweepCommand(CLI::App& app, std::vector<std::string> commandLine) {
    auto o = std::make_shared<SweepOptions>();
    CLI::App* cmd = app.add_subcommand("sweep", "Every combination of lights, resolution, MSAA and knobs through the "
                                                "pipelines: sweep.csv and sweep.html");
    cmd->add_option("scene", o->scene.scene, "Scene: a glTF 2.0 file or builtin:NAME (default builtin:courtyard)");
    cmd->add_option("--lights", o->lights, "Comma-separated generated light counts")->capture_default_str();
    cmd->add_option("--seed", o->scene.seed, "Seed of the light generator")->capture_default_str();
    cmd->add_option("--light-types", o->scene.lightTypes, "Generated light type mix, e.g. point:3,spot:1")->capture_default_str();
    cmd->add_flag("--no-scene-lights", o->scene.dropSceneLights, "Ignore lights defined in the glTF file");
    cmd->add_option("--res", o->res, "Comma-separated resolutions WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--msaa", o->msaa, "Comma-separated sample counts")->capture_default_str();
    cmd->add_option("--tile", o->tile, "Comma-separated tile sizes (tiled pipelines)")->capture_default_str();
    cmd->add_option("--light-lists", o->lightLists, "Comma-separated Forward+ list layouts")->capture_default_str();
    cmd->add_option("--gbuffer", o->gbuffer, "Comma-separated deferred G-buffer layouts")->capture_default_str();
    cmd->add_option("--accum", o->accum, "Comma-separated multipass accumulation precisions")->capture_default_str();
    cmd->add_option("--pipelines", o->pipelines, "Comma-separated pipelines (default: all)");
    cmd->add_option("--frames", o->frames, "Timed frames per run")->capture_default_str();
    cmd->add_option("--warmup", o->warmup, "Warm-up frames per run")->capture_default_str();
    cmd->add_option("--out", o->out, "Output directory")->capture_default_str();
    addDeviceOptions(*cmd, o->device);
    return [o, cmd, commandLine]() { return cmd->parsed() ? run(*o, commandLine) : -1; };
}

} // namespace tp::cli
