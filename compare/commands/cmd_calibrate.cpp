// triptych calibrate: this device's measured ceilings (core/calibrate/calibration.h) written
// to a JSON file keyed by the device, its driver and the triptych build, and reused from it
// by the next run with the same key (docs/efficiency.md). A file of another key, or one that
// does not parse, is measured again and replaced, never trusted.
#include <cstdio>
#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>
#include <CLI/CLI.hpp>

#include "compare/cache/calibration_cache.h"
#include "core/cli/cli_common.h"
#include "compare/commands/commands.h"
#include "core/calibrate/calibration.h"
#include "core/gpu/context.h"
#include "core/util/files.h"

namespace tp::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct CalibrateOptions {
    DeviceOptions device;
    std::string out; // empty: the user's cache folder, named by the key
    bool quick = false, force = false;
    int repeats = 7;
};

void printTable(const json& file) {
    // Four significant digits: the ceilings span 1e-3 (lavapipe's triangles) to 1e4 (H100's GB/s).
    std::printf("%-22s %10s %10s %10s  %-9s  %s\n", "ceiling", "median", "min", "max", "unit", "what");
    for (const json& c : file["ceilings"])
        std::printf("%-22s %10.4g %10.4g %10.4g  %-9s  %s\n", c["name"].get<std::string>().c_str(),
                    c["median"].get<double>(), c["min"].get<double>(), c["max"].get<double>(),
                    c["unit"].get<std::string>().c_str(), c["what"].get<std::string>().c_str());
    std::printf("on %s (%s), measured %s\n", file["key"]["device"].get<std::string>().c_str(),
                file["key"]["driver"].get<std::string>().c_str(),
                file["measured_at"].get<std::string>().c_str());
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
    const std::string path = o.out.empty() ? cachedCalibrationPath(key) : o.out;
    if (path.empty()) throw UsageError("calibrate: no cache folder (neither XDG_CACHE_HOME nor HOME): give --out FILE");
    const std::optional<json> existing = readCalibration(path);
    std::string why;
    if (existing && !o.force) {
        if (std::optional<json> file = reusableCalibration(*existing, key, why)) {
            std::fprintf(stderr, "triptych: calibration of %s reused from %s (measured %s; --force measures again)\n",
                         ctx->info.name.c_str(), path.c_str(), (*file)["measured_at"].get<std::string>().c_str());
            printTable(*file);
            return 0;
        }
        std::fprintf(stderr, "triptych: %s is %s: measuring again\n", path.c_str(), why.c_str());
    }
    const json file = measureCalibration(*ctx, key, path, uint32_t(o.repeats), commandLine);
    printTable(file);
    std::fprintf(stderr, "triptych: wrote %s\n", path.c_str());
    return validationExit(ctx->validationMessages());
}

} // namespace

CommandRunner addCalibrateCommand(CLI::App& app, std::vector<std::string> commandLine) {
    auto o = std::make_shared<CalibrateOptions>();
    CLI::App* cmd = app.add_subcommand(
        "calibrate",
        "Measure this device's ceilings with microbenchmarks (DRAM read/write/copy and cache bandwidth; FP32 FMA, "
        "texture fetch and our light model's rate in compute and in a fragment shader; depth, colour, blend and "
        "4x MSAA raster rates; triangle rates; shared and global atomics), and keep them in a JSON file "
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
