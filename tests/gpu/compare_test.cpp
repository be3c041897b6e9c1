// triptych compare end to end on courtyard-small at 96x54 with 8 lights and one frame:
// every promised file, a report.json that holds what docs/report.md promises, an offline
// report.html, and a failing configuration recorded as failed while the others go on.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <utility>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include "compare/commands/commands.h"
#include "compare/commands/compare.h"
#include "compare/commands/sweep.h"
#include "compare/report/report_html.h"
#include "compare/report/svg_plot.h"
#include "core/camera/camera_file.h"
#include "core/image/image_io.h"
#include "core/image/metrics.h"
#include "core/image/tonemap.h"
#include "core/renderer/renderer.h"
#include "temp_path.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::vector<std::string> pipelinesButReference() {
    std::vector<std::string> names;
    for (const RendererEntry& e : registeredRenderers())
        if (e.name != "reference") names.push_back(e.name);
    return names;
}

// Runs `triptych compare ARGS` through the real CLI definition.
int runCli(std::vector<std::string> args) {
    CLI::App app;
    std::vector<std::string> argv = {"triptych", "compare"};
    argv.insert(argv.end(), args.begin(), args.end());
    cli::CommandRunner runner = cli::addCompareCommand(app, argv);
    std::vector<char*> raw;
    for (std::string& a : argv)
        raw.push_back(a.data());
    app.parse(int(raw.size()), raw.data());
    return runner();
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

void expectMetrics(const json& m, const std::string& where) {
    for (const MetricInfo& info : metricTable())
        EXPECT_TRUE(m.contains(info.name)) << where << " lacks " << info.name;
    EXPECT_EQ(m["compared_pixels"].get<uint64_t>(), 96u * 54u) << where;
    EXPECT_EQ(m["nan_inf"].get<double>(), 0.0) << where;
}

void expectMemoryTotal(const json& memory, const std::string& where) {
    uint64_t sum = 0;
    for (const json& e : memory["resources"])
        sum += e["bytes"].get<uint64_t>();
    EXPECT_EQ(memory["total_bytes"].get<uint64_t>(), sum) << where;
    EXPECT_GT(sum, 0u) << where;
}

// One pipeline's entry in report.json: its run (timings on `device`, memory), its error
// against the reference (metrics, FLIP) and no dropped lights.
void expectPipelineEntry(const json& p, const std::string& name, const std::string& device) {
    EXPECT_EQ(p["name"], name);
    ASSERT_EQ(p["status"], "ok") << p.value("error", "");
    ASSERT_GE(p["run"]["timings"].size(), 2u); // "frame" and at least one pass
    EXPECT_EQ(p["run"]["timings"][0]["pass"], "frame");
    for (const json& t : p["run"]["timings"]) {
        EXPECT_EQ(t["device"], device);
        EXPECT_LE(t["min_ms"].get<double>(), t["median_ms"].get<double>());
        EXPECT_LE(t["median_ms"].get<double>(), t["max_ms"].get<double>());
    }
    expectMemoryTotal(p["run"]["memory"], name);
    EXPECT_DOUBLE_EQ(p["run"]["memory"]["bytes_per_pixel"].get<double>(),
                     p["run"]["memory"]["total_bytes"].get<double>() / (96.0 * 54.0));
    for (const json& e : p["run"]["memory"]["resources"])
        EXPECT_NE(e["name"], "vertices"); // scene is shared
    expectMetrics(p["error_vs_reference"]["hdr"], "hdr");
    expectMetrics(p["error_vs_reference"]["tonemapped"], "tonemapped");
    for (const char* kind : {"ldr", "hdr"}) {
        const json& f = p["error_vs_reference"]["flip"][kind];
        for (const char* k :
             {"mean", "weighted_median", "weighted_q1", "weighted_q3", "min", "max"}) {
            ASSERT_TRUE(f[k].is_number()) << kind << " " << k;
            EXPECT_GE(f[k].get<double>(), 0.0);
            EXPECT_LE(f[k].get<double>(), 1.0);
        }
    }
    EXPECT_GE(p["error_vs_reference"]["flip"]["hdr"]["exposures"].get<int>(), 2);
    EXPECT_EQ(p["lights_dropped"].get<double>(), 0.0);
}

// One pair's entry in report.json: its files, metrics, and an EXR of a - b that agrees with
// them.
void expectPairEntry(const json& pair, const std::string& out) {
    const std::string stem =
        pair["a"].get<std::string>() + "_vs_" + pair["b"].get<std::string>() + "_diff";
    EXPECT_EQ(pair["files"], json({stem + ".exr", stem + ".png"}));
    expectMetrics(pair["hdr"], stem);
    expectMetrics(pair["tonemapped"], stem);
    Result<ImageRGBA> diff = readExr(out + "/" + stem + ".exr");
    ASSERT_TRUE(diff.ok()) << diff.error();
    // The EXR holds float(a - b): within one float rounding (2^-24 relative) of the metric's
    // difference, which is taken in double.
    const double maxAbs = pair["hdr"]["max_abs"].get<double>();
    EXPECT_NEAR(computeError(*diff, ImageRGBA(96, 54)).maxAbs, maxAbs, maxAbs * 0x1p-24) << stem;
    EXPECT_TRUE(fs::exists(out + "/" + stem + ".png")) << stem;
}

TEST(Compare, EveryPipelineWritesEveryFileAndAReport) {
    const std::string out = freshDir("compare_all");
    int rc = runCli({"builtin:courtyard-small", "--res", "96x54", "--lights", "8", "--seed", "3",
                     "--frames", "1", "--warmup", "0", "--validate", "--out", out});
    ASSERT_EQ(rc, 0);
    const std::vector<std::string> names = pipelinesButReference();
    ASSERT_FALSE(names.empty());
    for (const char* f :
         {"reference.exr", "reference.png", "lights.json", "report.json", "report.html"})
        EXPECT_TRUE(fs::exists(out + "/" + f)) << f;
    for (const std::string& n : names)
        for (const char* suffix : {".exr", ".png", "_diff.exr", "_diff.png", "_flip.exr",
                                   "_flip.png", "_flip_ldr.exr", "_flip_ldr.png"})
            EXPECT_TRUE(fs::exists(out + "/" + n + suffix)) << n << suffix;

    json r = json::parse(readText(out + "/report.json"));
    EXPECT_EQ(r["schema"], "triptych.report/2");
    EXPECT_NEAR(r["flip"]["pixels_per_degree"].get<double>(), 67.02, 0.01);
    EXPECT_EQ(r["status"], "ok");
    EXPECT_EQ(r["seed"].get<uint64_t>(), 3u);
    EXPECT_EQ(r["scene"]["path"], "builtin:courtyard-small");
    EXPECT_EQ(r["command_line"].back(), out);
    EXPECT_TRUE(r["validation_messages"].empty());
    const std::string device = r["device"]["name"];
    EXPECT_FALSE(device.empty());
    expectMemoryTotal(r["shared_memory"], "scene");
    ASSERT_EQ(r["pipelines"].size(), names.size());
    float largestP99 = 0;
    for (size_t i = 0; i < names.size(); ++i) {
        const json& p = r["pipelines"][i];
        SCOPED_TRACE(names[i]);
        ASSERT_NO_FATAL_FAILURE(expectPipelineEntry(p, names[i], device));
        largestP99 = std::max(largestP99, p["difference_p99"].get<float>());
    }
    EXPECT_FLOAT_EQ(r["difference_scale"]["value"].get<float>(), std::max(largestP99, 1e-6f));
    EXPECT_EQ(r["pairwise"].size(), names.size() * (names.size() - 1) / 2);
    for (const json& pair : r["pairwise"]) { // a - b as EXR and heat map, listed in the report
        ASSERT_NO_FATAL_FAILURE(expectPairEntry(pair, out));
    }

    // One exposure for every PNG: the automatic one of the reference image as written.
    Result<ImageRGBA> ref = readExr(out + "/reference.exr");
    ASSERT_TRUE(ref.ok()) << ref.error();
    EXPECT_FLOAT_EQ(r["settings"]["exposure_ev"].get<float>(), autoExposureEv(*ref));

    const std::string html = readText(out + "/report.html");
    EXPECT_EQ(count(html, "http://"), 0u);
    EXPECT_EQ(count(html, "https://"), 0u);
    const size_t pairs = names.size() * (names.size() - 1) / 2;
    // The reference; per pipeline its image, difference map and HDR-FLIP map; per pair its map.
    EXPECT_EQ(count(html, "src=\"data:image/png;base64,"), 1 + 3 * names.size() + pairs);
    EXPECT_GE(count(html, "<svg"), 2u); // timing bars and the error/time plot
    for (const std::string& n : names)
        EXPECT_NE(html.find(n), std::string::npos);
}

TEST(Compare, FailingPipelineIsRecordedAndTheOthersGoOn) {
    const std::string out = freshDir("compare_fail");
    fs::create_directories(out);
    { std::ofstream(out + "/report.json") << "{\"stale\": true}"; } // must not survive
    cli::CompareOptions o;
    o.scene.scene = "builtin:courtyard-small";
    o.scene.lightCount = 4;
    o.view.resolution = "96x54";
    o.frames = 1;
    o.warmup = 0;
    o.out = out;
    o.pipelines = "forwardplus,multipass_forward";
    o.knobs.set("light-lists", "fixed");
    o.knobs.set("tile-capacity", 0u); // refused by the CLI; forwardplus cannot be built with it
    EXPECT_EQ(cli::runCompare(o), 5);
    json r = json::parse(readText(out + "/report.json"));
    EXPECT_FALSE(r.contains("stale"));
    EXPECT_EQ(r["status"], "failed");
    ASSERT_EQ(r["pipelines"].size(), 2u);
    EXPECT_EQ(r["pipelines"][0]["status"], "failed");
    EXPECT_NE(r["pipelines"][0]["error"].get<std::string>().find("capacity"), std::string::npos);
    EXPECT_FALSE(fs::exists(out + "/forwardplus.png"));
    EXPECT_EQ(r["pipelines"][1]["status"], "ok");
    EXPECT_TRUE(fs::exists(out + "/multipass_forward_diff.png"));
    EXPECT_NE(readText(out + "/report.html").find("forwardplus failed"), std::string::npos);
}

// report.json without what legitimately changes between two runs of one command: the
// output directory in the command line, and the timings.
// A report without what is measured: the timings and the energy (a device with a counter,
// e.g. NVML on a GPU, gives other joules and another window every run).
json withoutTimings(json r) {
    r.erase("command");
    r.erase("command_line");
    for (const char* measured : {"timings", "energy"}) {
        r["reference"]["run"].erase(measured);
        for (json& p : r["pipelines"])
            p["run"].erase(measured);
    }
    return r;
}

// The same command on the same device: identical images (byte for byte) and an identical
// report but for the timings and the energy; the report names the scene by hashes of its data.
// Both render their reference (--no-reference-cache): the second would otherwise read the
// first's.
TEST(Compare, SameCommandTwiceGivesIdenticalImagesAndMetrics) {
    std::vector<std::string> dirs = {freshDir("repeat_a"), freshDir("repeat_b")};
    for (const std::string& out : dirs)
        ASSERT_EQ(runCli({"builtin:courtyard-small", "--res", "96x54", "--lights", "16", "--seed",
                          "5", "--frames", "2", "--warmup", "0", "--no-reference-cache", "--out",
                          out}),
                  0);
    json a = json::parse(readText(dirs[0] + "/report.json"));
    json b = json::parse(readText(dirs[1] + "/report.json"));
    EXPECT_EQ(withoutTimings(a), withoutTimings(b));
    EXPECT_EQ(a["scene"]["content_hash_fnv1a64"].get<std::string>().size(), 16u);
    EXPECT_EQ(a["scene"]["lights_hash_fnv1a64"].get<std::string>().size(), 16u);
    EXPECT_TRUE(a["scene"]["files_hash_fnv1a64"].is_null()); // a built-in scene has no file
    size_t images = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(dirs[0])) {
        const std::string name = e.path().filename().string();
        if (e.path().extension() != ".exr" && e.path().extension() != ".png" &&
            name != "lights.json")
            continue;
        ++images;
        EXPECT_TRUE(readText(e.path().string()) == readText(dirs[1] + "/" + name))
            << name << " differs";
    }
    const size_t n = pipelinesButReference().size();
    // lights, reference, pipelines (image, difference, FLIP and HDR-FLIP maps), pairs
    EXPECT_EQ(images, 1 + 2 + 8 * n + 2 * (n * (n - 1) / 2));
}

TEST(Compare, BadPipelineNameFailsBeforeWritingAnything) {
    const std::string out = freshDir("compare_bad");
    EXPECT_THROW(
        runCli({"builtin:courtyard-small", "--pipelines", "forwardplus,nosuch", "--out", out}),
        cli::UsageError);
    EXPECT_FALSE(fs::exists(out));
}

// sweep.csv as one map per row, keyed by the header's column names.
std::vector<std::map<std::string, std::string>> readCsv(const std::string& path) {
    std::stringstream csv(readText(path));
    std::string line;
    std::getline(csv, line);
    std::vector<std::string> header;
    std::stringstream hs(line);
    for (std::string f; std::getline(hs, f, ',');)
        header.push_back(f);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(csv, line)) {
        std::vector<std::string> fields;
        std::string field;
        bool quoted = false;
        for (char c : line) { // the device name is quoted: it holds commas
            if (c == '"')
                quoted = !quoted;
            else if (c == ',' && !quoted)
                fields.push_back(std::exchange(field, ""));
            else
                field += c;
        }
        fields.push_back(field);
        EXPECT_EQ(fields.size(), header.size()) << line;
        std::map<std::string, std::string> row;
        for (size_t i = 0; i < std::min(fields.size(), header.size()); ++i)
            row[header[i]] = fields[i];
        rows.push_back(row);
    }
    return rows;
}

int runSweepCli(std::vector<std::string> args) {
    CLI::App app;
    std::vector<std::string> argv = {"triptych", "sweep"};
    argv.insert(argv.end(), args.begin(), args.end());
    cli::CommandRunner runner = cli::addSweepCommand(app, argv);
    std::vector<char*> raw;
    for (std::string& a : argv)
        raw.push_back(a.data());
    app.parse(int(raw.size()), raw.data());
    return runner();
}

// --shard K/N and merge: three shards of a sweep (each a third of the runs, the reference
// where its rows land or read from the cache), merged in any order, give the unsharded
// sweep's rows in its order, every column but the frame timings equal, and its sweep id;
// shards of another sweep, a missing one and a repeated one are refused with one line.
TEST(Compare, ShardedAndMergedSweepEqualsTheWholeSweep) {
    const std::string base = freshDir("shards");
    const std::vector<std::string> args = {
        "builtin:courtyard-small", "--res", "64x36", "--lights", "4,8", "--msaa", "1,4",
        "--tile", "8,16", "--pipelines", "forwardplus,deferred", "--frames", "1", "--warmup",
        "0", "--reference-cache", base + "/cache"};
    auto sweep = [&](const std::string& out, std::vector<std::string> extra) {
        std::vector<std::string> a = args;
        a.insert(a.end(), extra.begin(), extra.end());
        a.insert(a.end(), {"--out", base + "/" + out});
        return runSweepCli(a);
    };
    ASSERT_EQ(sweep("whole", {}), 0);
    for (int k : {2, 0, 1})
        ASSERT_EQ(sweep("s" + std::to_string(k), {"--shard", std::to_string(k) + "/3"}), 0);
    ASSERT_EQ(cli::runMerge({base + "/s1", base + "/s2", base + "/s0"}, base + "/merged"), 0);
    auto withoutTimings = [](std::vector<std::map<std::string, std::string>> rows) {
        for (auto& r : rows)
            for (const char* c :
                 {"frame_median_ms", "frame_min_ms", "frame_max_ms", "joules_per_frame"})
                r.erase(c);
        return rows;
    };
    const auto whole = readCsv(base + "/whole/sweep.csv");
    EXPECT_EQ(whole.size(), 20u);
    EXPECT_EQ(withoutTimings(readCsv(base + "/merged/sweep.csv")), withoutTimings(whole));
    const json a = json::parse(readText(base + "/whole/sweep.json"));
    const json b = json::parse(readText(base + "/merged/sweep.json"));
    EXPECT_EQ(a["sweep_id_fnv1a64"], b["sweep_id_fnv1a64"]);
    ASSERT_EQ(a["runs"].size(), b["runs"].size());
    for (size_t i = 0; i < a["runs"].size(); ++i)
        EXPECT_EQ(a["runs"][i]["settings"], b["runs"][i]["settings"]) << i;
    // Refusals, before anything is written.
    ASSERT_EQ(sweep("other", {"--seed", "9", "--shard", "1/3"}), 0); // other lights
    for (const std::vector<std::string>& dirs :
         {std::vector<std::string>{base + "/s0", base + "/other", base + "/s2"},
          std::vector<std::string>{base + "/s0", base + "/s1"},
          std::vector<std::string>{base + "/s0", base + "/s0", base + "/s1", base + "/s2"}})
        EXPECT_THROW(cli::runMerge(dirs, base + "/refused"), cli::UsageError);
    EXPECT_FALSE(fs::exists(base + "/refused/sweep.csv"));
}

TEST(Compare, SweepWritesOneRowPerRun) {
    const std::string out = freshDir("sweep");
    ASSERT_EQ(runSweepCli({"builtin:courtyard-small", "--lights", "4,8", "--res", "96x54", "--tile",
                           "8,16", "--deferred-lighting", "tiled,volumes", "--frames", "1",
                           "--warmup", "0", "--out", out}),
              0);
    std::map<std::string, int> runs; // pipeline/lights -> rows
    std::set<std::string> tiles, lighting;
    const auto rows = readCsv(out + "/sweep.csv");
    for (const auto& row : rows) {
        EXPECT_EQ(row.at("status"), "ok") << row.at("pipeline");
        ++runs[row.at("pipeline") + "/" + row.at("lights")];
        if (row.at("pipeline") == "forwardplus") tiles.insert(row.at("tile"));
        if (row.at("pipeline") == "deferred") lighting.insert(row.at("deferred_lighting"));
        const bool pipeline = row.at("pipeline") != "reference";
        for (const char* column :
             {"rmse_hdr", "psnr_hdr", "max_abs_hdr", "rmse_tonemapped", "psnr_tonemapped",
              "max_abs_tonemapped", "flip_hdr_mean", "flip_tonemapped_mean"})
            EXPECT_EQ(row.at(column).empty(), !pipeline) << row.at("pipeline") << " " << column;
    }
    for (const RendererEntry& e : registeredRenderers())
        for (const char* lights : {"4", "8"})
            EXPECT_GE(runs[e.name + "/" + lights], 1) << e.name << " " << lights;
    EXPECT_EQ(runs["reference/4"], 1);         // once per light set
    EXPECT_EQ(runs["deferred/4"], 4);          // 2 tiles x 2 lighting modes
    EXPECT_EQ(runs["multipass_forward/4"], 1); // reads neither knob
    EXPECT_EQ(tiles, (std::set<std::string>{"8", "16"}));
    EXPECT_EQ(lighting, (std::set<std::string>{"tiled", "volumes"}));

    // sweep.json: one entry per row, with every pass's timings, the ledger and every metric.
    json j = json::parse(readText(out + "/sweep.json"));
    EXPECT_EQ(j["schema"], "triptych.sweep/2");
    EXPECT_EQ(j["command_line"][1], "sweep");
    EXPECT_EQ(j["scene"]["content_hash_fnv1a64"].get<std::string>().size(), 16u);
    ASSERT_EQ(j["runs"].size(), rows.size());
    for (size_t i = 0; i < rows.size(); ++i) {
        const json& run = j["runs"][i];
        SCOPED_TRACE(rows[i].at("pipeline"));
        EXPECT_EQ(run["pipeline"], rows[i].at("pipeline"));
        EXPECT_EQ(run["settings"]["deferred_lighting"], rows[i].at("deferred_lighting"));
        ASSERT_GE(run["run"]["timings"].size(), 2u); // the frame and each pass
        EXPECT_EQ(run["run"]["timings"][0]["pass"], "frame");
        EXPECT_EQ(std::to_string(run["run"]["memory"]["total_bytes"].get<uint64_t>()),
                  rows[i].at("memory_bytes"));
        expectMemoryTotal(run["run"]["memory"], rows[i].at("pipeline"));
        if (run["pipeline"] == "reference") {
            EXPECT_TRUE(run["error_vs_reference"].is_null());
            continue;
        }
        expectMetrics(run["error_vs_reference"]["hdr"], "hdr");
        expectMetrics(run["error_vs_reference"]["tonemapped"], "tonemapped");
    }
    const std::string html = readText(out + "/sweep.html");
    EXPECT_EQ(count(html, "http"), 0u);
    EXPECT_EQ(count(html, "<svg"), 4u); // time, memory, error (RMSE and HDR-FLIP) plots
    // Every run is a point of the time and memory plots (r="6": a point; the legend's are 5).
    const size_t first = html.find("<svg"), second = html.find("<svg", first + 1),
                 third = html.find("<svg", second + 1);
    EXPECT_EQ(count(html.substr(first, second - first), "r=\"6\""), rows.size());
    EXPECT_EQ(count(html.substr(second, third - second), "r=\"6\""), rows.size());
    EXPECT_NE(html.find("pipeline memory (MB)"), std::string::npos);
}

// --camera FILE: the view changes (another image, another camera and content hash), report.json
// and sweep.json record the camera and its source, and the report's "camera" object (or
// camera.json) is itself a camera file that gives back the same images.
TEST(Compare, CameraFileChangesTheViewAndRoundTrips) {
    const std::string pipeline = pipelinesButReference().front();
    const std::vector<std::string> common = {"builtin:courtyard-small",
                                             "--res",
                                             "64x36",
                                             "--lights",
                                             "8",
                                             "--frames",
                                             "1",
                                             "--warmup",
                                             "0",
                                             "--pipelines",
                                             pipeline};
    auto compareInto = [&](const std::string& out, std::vector<std::string> extra) {
        std::vector<std::string> args = common;
        args.insert(args.end(), extra.begin(), extra.end());
        args.insert(args.end(), {"--validate", "--out", out});
        EXPECT_EQ(runCli(args), 0) << out;
        return json::parse(readText(out + "/report.json"));
    };
    const std::string base = freshDir("camera_default"), moved = freshDir("camera_file"),
                      again = freshDir("camera_again");
    json a = compareInto(base, {});
    EXPECT_EQ(a["camera_source"]["kind"], "scene");
    Result<Camera> defaultCamera = cameraFromJson(a["camera"], "report.json camera");
    ASSERT_TRUE(defaultCamera.ok()) << defaultCamera.error();
    Result<Camera> written = readCameraFile(base + "/camera.json");
    ASSERT_TRUE(written.ok()) << written.error();
    EXPECT_EQ(cameraToJson(*written), a["camera"]);

    Camera view = *defaultCamera; // turned and moved: another view of the same scene
    view.position += glm::vec3(1.5f, 0.5f, -3.0f);
    view.yfov *= 0.8f;
    const std::string file = fs::path(moved).parent_path().string() + "/triptych_view_" +
                             std::to_string(getpid()) + ".json";
    ASSERT_TRUE(writeCameraFile(file, view).ok());
    json b = compareInto(moved, {"--camera", file});
    EXPECT_EQ(b["camera"], cameraToJson(view));
    EXPECT_EQ(b["camera_source"]["kind"], "file");
    EXPECT_EQ(b["camera_source"]["path"], file);
    EXPECT_NE(b["scene"]["camera_hash_fnv1a64"], a["scene"]["camera_hash_fnv1a64"]);
    EXPECT_NE(b["scene"]["content_hash_fnv1a64"], a["scene"]["content_hash_fnv1a64"]);
    EXPECT_EQ(b["scene"]["lights_hash_fnv1a64"],
              a["scene"]["lights_hash_fnv1a64"]); // only the view changed
    for (const std::string& image : {std::string("reference.exr"), pipeline + ".exr"})
        EXPECT_FALSE(readText(base + "/" + image) == readText(moved + "/" + image))
            << image << ": same image";

    // The report's camera object as the next run's --camera: the same view, bit for bit.
    const std::string fromReport = file + ".from_report.json";
    std::ofstream(fromReport) << b["camera"].dump(2);
    json c = compareInto(again, {"--camera", fromReport});
    EXPECT_EQ(c["scene"]["camera_hash_fnv1a64"], b["scene"]["camera_hash_fnv1a64"]);
    EXPECT_EQ(c["scene"]["content_hash_fnv1a64"], b["scene"]["content_hash_fnv1a64"]);
    for (const std::string& image : {std::string("reference.exr"), pipeline + ".exr"})
        EXPECT_TRUE(readText(moved + "/" + image) == readText(again + "/" + image))
            << image << " differs";

    const std::string sweep = freshDir("camera_sweep");
    ASSERT_EQ(runSweepCli({"builtin:courtyard-small", "--res", "64x36", "--lights", "4", "--frames",
                           "1", "--warmup", "0", "--reference-frames", "0", "--pipelines", pipeline,
                           "--camera", file, "--out", sweep}),
              0);
    json s = json::parse(readText(sweep + "/sweep.json"));
    EXPECT_EQ(s["camera"], cameraToJson(view));
    EXPECT_EQ(s["camera_source"]["kind"], "file");
    EXPECT_EQ(s["scene"]["camera_hash_fnv1a64"], b["scene"]["camera_hash_fnv1a64"]);
    if (!HasFailure())
        for (const std::string& p : {base, moved, again, sweep, file, fromReport})
            fs::remove_all(p);
}

// Under MSAA: the second reference (--reference-msaa center), each pipeline's error against
// both, the rate it ran, both plots in report.html, and the *_center columns in sweep.csv;
// --no-center-reference leaves it out.
TEST(Compare, MsaaReportsErrorAgainstBothReferences) {
    const std::string out = freshDir("compare_msaa");
    ASSERT_EQ(runCli({"builtin:courtyard-small", "--res", "96x54", "--msaa", "4", "--lights", "8",
                      "--frames", "1", "--warmup", "0", "--validate", "--out", out}),
              0);
    EXPECT_TRUE(fs::exists(out + "/reference_center.exr"));
    json r = json::parse(readText(out + "/report.json"));
    ASSERT_TRUE(r["center_reference"]["rendered"].get<bool>());
    EXPECT_GT(r["center_reference"]["error_vs_reference"]["hdr"]["rmse"].get<double>(), 0.0);
    for (const json& p : r["pipelines"]) {
        SCOPED_TRACE(p["name"].get<std::string>());
        expectMetrics(p["error_vs_center_reference"]["hdr"], "hdr");
        EXPECT_EQ(p["run"]["msaa_shading"], "pixel");
    }
    const std::string html = readText(out + "/report.html");
    EXPECT_NE(html.find("Two errors under MSAA"), std::string::npos);
    EXPECT_GE(count(html, "<svg"), 3u); // timing bars and the two error/time plots

    const std::string off = freshDir("compare_msaa_off");
    ASSERT_EQ(runCli({"builtin:courtyard-small", "--res", "96x54", "--msaa", "4", "--lights", "8",
                      "--frames", "1", "--warmup", "0", "--pipelines", "forwardplus",
                      "--no-center-reference", "--out", off}),
              0);
    EXPECT_FALSE(fs::exists(off + "/reference_center.exr"));
    EXPECT_FALSE(
        json::parse(readText(off + "/report.json"))["center_reference"]["rendered"].get<bool>());

    const std::string sweep = freshDir("sweep_msaa");
    ASSERT_EQ(runSweepCli({"builtin:courtyard-small", "--lights", "4", "--res", "96x54", "--msaa",
                           "4", "--pipelines", "forwardplus", "--msaa-shading", "pixel,sample",
                           "--frames", "1", "--warmup", "0", "--out", sweep}),
              0);
    for (const auto& row : readCsv(sweep + "/sweep.csv")) {
        const bool pipeline = row.at("pipeline") != "reference";
        EXPECT_EQ(row.at("rmse_hdr_center").empty(), !pipeline) << row.at("pipeline");
        EXPECT_EQ(row.at("psnr_tonemapped_center").empty(), !pipeline) << row.at("pipeline");
    }
    // sweep.html: time, memory, RMSE and HDR-FLIP plots, and the error against the centre
    // reference.
    const std::string sweepPage = readText(sweep + "/sweep.html");
    EXPECT_EQ(count(sweepPage, "<svg"), 5u);
    EXPECT_NE(sweepPage.find("RMSE vs centre reference"), std::string::npos);
}

// A configuration that cannot run is a failed row with its reason, the others still run and
// the files are written; exit code 5. Without a reference (--reference-frames 0) there are
// no error figures.
TEST(Compare, SweepRecordsAFailedRunAndGoesOn) {
    const std::string out = freshDir("sweep_fail");
    cli::SweepOptions o;
    o.scene.scene = "builtin:courtyard-small";
    o.lights = "4";
    o.res = "96x54";
    o.knobs["light-lists"] = "fixed,compact";
    o.knobs["tile-capacity"] = "0"; // refused by the CLI; no Forward+ run can be built with it
    o.frames = 1;
    o.warmup = 0;
    o.referenceFrames = 0;
    o.pipelines = "forwardplus,multipass_forward";
    o.out = out;
    EXPECT_EQ(cli::runSweep(o), 5);
    const auto rows = readCsv(out + "/sweep.csv");
    ASSERT_EQ(rows.size(), 3u); // forwardplus fixed, forwardplus compact, multipass_forward
    for (int i : {0, 1}) {      // the knob's check refuses 0 whatever the layout
        EXPECT_EQ(rows[i].at("pipeline"), "forwardplus");
        EXPECT_EQ(rows[i].at("status"), "failed");
        EXPECT_NE(rows[i].at("error").find("--tile-capacity '0'"), std::string::npos)
            << rows[i].at("error");
    }
    EXPECT_EQ(rows[2].at("status"), "ok");
    for (const auto& row : rows)
        EXPECT_TRUE(row.at("rmse_hdr").empty());
    json j = json::parse(readText(out + "/sweep.json"));
    EXPECT_EQ(j["runs"][0]["status"], "failed");
    EXPECT_EQ(j["runs"][0]["error"], rows[0].at("error"));
    const std::string page = readText(out + "/sweep.html");
    EXPECT_NE(page.find("Failed runs"), std::string::npos);
    // The error plots say why they are empty instead of drawing empty axes.
    EXPECT_EQ(count(page, "ran without a reference (--reference-frames 0)"), 2u);
    EXPECT_EQ(count(page, "<svg"), 2u); // time and memory

    o.knobs["deferred-lighting"] = "tiled,sideways"; // bad input: refused before anything runs
    o.out = freshDir("sweep_bad");
    EXPECT_THROW(cli::runSweep(o), cli::UsageError);
    EXPECT_FALSE(fs::exists(o.out));
}

TEST(Compare, HtmlHelpers) {
    EXPECT_EQ(cli::base64(""), "");
    EXPECT_EQ(cli::base64("M"), "TQ==");
    EXPECT_EQ(cli::base64("Ma"), "TWE=");
    EXPECT_EQ(cli::base64("Man"), "TWFu");
    EXPECT_EQ(cli::escapeXml("<a href=\"x\">&'"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;");
    std::string svg = cli::scatterLogLogSvg({{"a", 10, 1e-3}, {"b", 100, 0}}, "x", "y");
    EXPECT_EQ(count(svg, "<circle"), 2u);
    EXPECT_NE(svg.find(">a</text>"), std::string::npos);
}

} // namespace
} // namespace tp::test
