// triptych calibrate: this device's measured ceilings (core/calibrate/calibration.h) written
// to a JSON file keyed by the device, its driver and the triptych build, and reused from it
// by the next run with the same key (docs/efficiency.md). A file of another key, or one that
// does not parse, is measured again and replaced, never trusted.
#include <cstdio>
#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>
#include <CLI/CLI.hpp>

#include "compare/build_identity.h"
#include "compare/cli_common.h"
#include "compare/commands.h"
#include "compare/scene_hash.h"
#include "core/calibrate/calibration.h"
#include "core/gpu/context.h"
#include "core/util/files.h"

namespace tp::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
constexpr const char* kSchema = "triptych.calibration/1";

struct CalibrateOptions {
    DeviceOptions device;
    std::string out; // empty: the user's cache folder, named by the key
    bool quick = false, force = false;
    int repeats = 7;
};

// What a calibration is valid for: this device, driver and build, and the mode.
json calibrationKey(const GpuContext& ctx, bool quick) {
    return {{"device", ctx.info.name}, {"driver", ctx.info.driver}, {"type", ctx.info.type},
            {"build_fnv1a64", buildHash()}, {"quick", quick}};
}

std::string keyHash(const json& key) {
    Fnv1a64 h;
    h.text(key.dump());
    return h.hex();
}

json ceilingsToJson(const std::vector<Ceiling>& ceilings) {
    json out = json::array();
    for (const Ceiling& c : ceilings)
        out.push_back({{"name", c.name}, {"unit", c.unit}, {"what", c.what}, {"median", c.median},
                       {"min", c.min}, {"max", c.max}, {"median_ms", c.medianMs}, {"work", c.work},
                       {"repeats", c.repeats}});
    return out;
}

void printTable(const json& file) {
    std::printf("%-14s %12s %12s %12s  %-9s  %s\n", "ceiling", "median", "min", "max", "unit", "what");
    for (const json& c : file["ceilings"])
        std::printf("%-14s %12.2f %12.2f %12.2f  %-9s  %s\n", c["name"].get<std::string>().c_str(),
                    c["median"].get<double>(), c["min"].get<double>(), c["max"].get<double>(),
                    c["unit"].get<std::string>().c_str(), c["what"].get<std::string>().c_str());
    std::printf("on %s (%s), measured %s\n", file["key"]["device"].get<std::string>().c_str(),
                file["key"]["driver"].get<std::string>().c_str(),
                file["measured_at"].get<std::string>().c_str());
}

bool isCalibration(const json& file) { return file.is_object() && file.value("schema", "") == kSchema; }

// Every field printTable reads, of the types it reads them as.
bool isComplete(const json& file) {
    if (!file.value("measured_at", json()).is_string() || !file.value("ceilings", json()).is_array())
        return false;
    for (const json& c : file["ceilings"])
        for (const char* k : {"median", "min", "max"})
            if (!c.is_object() || !c.value(k, json()).is_number() || !c.value("unit", json()).is_string() ||
                !c.value("what", json()).is_string() || !c.value("name", json()).is_string())
                return false;
    return file["key"].value("device", json()).is_string() && file["key"].value("driver", json()).is_string();
}

// The file at `path`: nothing when absent; else parsed (a value that is not a calibration when
// it does not parse).
std::optional<json> readCalibration(const std::string& path) {
    if (!fs::exists(path)) return std::nullopt;
    Result<std::string> text = readWholeFile(path);
    json file = text ? json::parse(*text, nullptr, false) : json();
    return file.is_discarded() ? json() : file;
}

// `file` when it is a complete calibration of `key` with this build's ceilings; else nothing,
// with `why` saying what was wrong.
std::optional<json> reusable(const json& file, const json& key, std::string& why) {
    if (!isCalibration(file) || !isComplete(file)) {
        why = "not a complete calibration";
        return std::nullopt;
    }
    if (file["key"] != key) {
        why = "made for another device, driver, build or mode";
        return std::nullopt;
    }
    std::vector<std::string> names;
    for (const json& c : file["ceilings"])
        names.push_back(c["name"]);
    if (names != ceilingNames()) {
        why = "its ceilings are not this build's";
        return std::nullopt;
    }
    return file;
}

int runCalibrate(const CalibrateOptions& o, const std::vector<std::string>& commandLine) {
    if (o.repeats < 1 || o.repeats > 1000) throw UsageError("calibrate: --repeats must be 1..1000");
    // A file the user named that is something else (a report, a typo) is never overwritten,
    // and is refused before any GPU work; in our own cache folder a damaged file is measured
    // again.
    if (!o.out.empty())
        if (std::optional<json> named = readCalibration(o.out); named && !isCalibration(*named))
            throw UsageError("calibrate: " + o.out +
                             " exists and is not a triptych calibration: not overwriting it (remove it, "
                             "or give another --out)");
    std::unique_ptr<GpuContext> ctx = createContext(o.device);
    const json key = calibrationKey(*ctx, o.quick);
    std::string path = o.out;
    if (path.empty()) {
        const std::string dir = userCacheDir("calibration");
        if (dir.empty()) throw UsageError("calibrate: no cache folder (neither XDG_CACHE_HOME nor HOME): give --out FILE");
        path = dir + "/" + keyHash(key) + ".json";
    }
    const std::optional<json> existing = readCalibration(path);
    std::string why;
    if (existing && !o.force) {
        if (std::optional<json> file = reusable(*existing, key, why)) {
            std::fprintf(stderr, "triptych: calibration of %s reused from %s (measured %s; --force measures again)\n",
                         ctx->info.name.c_str(), path.c_str(), (*file)["measured_at"].get<std::string>().c_str());
            printTable(*file);
            return 0;
        }
        std::fprintf(stderr, "triptych: %s is %s: measuring again\n", path.c_str(), why.c_str());
    }
    std::fprintf(stderr, "triptych: calibrating %s (%s), %d repeats after a warm-up%s\n", ctx->info.name.c_str(),
                 ctx->info.driver.c_str(), o.repeats, o.quick ? ", quick (small working sets)" : "");
    CalibrationOptions co;
    co.quick = o.quick;
    co.repeats = uint32_t(o.repeats);
    co.progress = [](const std::string& line) { std::fprintf(stderr, "triptych: %s\n", line.c_str()); };
    const std::vector<Ceiling> ceilings = measureCeilings(*ctx, co);
    const json file = {{"schema", kSchema}, {"key", key}, {"measured_at", utcNow()},
                       {"repeats", o.repeats}, {"command", commandLine}, {"ceilings", ceilingsToJson(ceilings)}};
    if (const fs::path parent = fs::path(path).parent_path(); !parent.empty()) ensureDirectory(parent.string());
    if (Status written = writeTextFile(path, file.dump(2) + "\n"); !written.ok())
        throw UsageError("calibrate: " + written.error());
    printTable(file);
    std::fprintf(stderr, "triptych: wrote %s\n", path.c_str());
    return validationExit(ctx->validationMessages());
}

} // namespace

CommandRunner addCalibrateCommand(CLI::App& app, std::vector<std::string> commandLine) {
    auto o = std::make_shared<CalibrateOptions>();
    CLI::App* cmd = app.add_subcommand(
        "calibrate",
        "Measure this device's ceilings (DRAM read/write/copy and cache bandwidth, FP32 FMA rate in compute and in a fragment shader, "
        "shared and global atomics) with compute microbenchmarks, and keep them in a JSON file "
        "keyed by device, driver and triptych build; a later run with the same key reuses the "
        "file (docs/efficiency.md). Exit 0 ok, 2 bad input, 3 validation messages");
    addDeviceOptions(*cmd, o->device);
    cmd->add_option("--out", o->out,
                    "The calibration file (default: $XDG_CACHE_HOME/triptych/calibration/KEY.json, "
                    "else ~/.cache/...). Reused when it holds this key, else measured and replaced");
    cmd->add_flag("--quick", o->quick,
                  "Small working sets and short loops (seconds on lavapipe): for tests; the DRAM "
                  "figures then fit in a large cache and are not DRAM's");
    cmd->add_option("--repeats", o->repeats, "Timed dispatches per ceiling, after one warm-up (median, min, max)")
        ->capture_default_str();
    cmd->add_flag("--force", o->force, "Measure again even when the file holds this key");
    return [o, cmd, commandLine]() {
        if (!cmd->parsed()) return -1;
        return runCalibrate(*o, commandLine);
    };
}

} // namespace tp::cli
