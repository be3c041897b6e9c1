#include "compare/cache/calibration_cache.h"

#include <cstdio>
#include <filesystem>

#include "compare/cache/build_identity.h"
#include "core/cli/cli_common.h"
#include "compare/cache/scene_hash.h"
#include "core/gpu/context.h"

namespace tp::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::shared_ptr<RunCalibration> usable(const json& file, const std::string& path) {
    auto cal = std::make_shared<RunCalibration>();
    cal->available = true;
    cal->path = path;
    cal->key = file["key"];
    cal->measuredAt = file["measured_at"];
    cal->rates = ceilingRatesOf(file).value_or(CeilingRates{}); // complete: checked by the caller
    return cal;
}

std::shared_ptr<RunCalibration> unavailable(const std::string& why) {
    auto cal = std::make_shared<RunCalibration>();
    cal->why = why;
    return cal;
}

// A named file: a complete calibration of this device and driver (another build's figures are
// used, and say so in the report through their key).
std::shared_ptr<RunCalibration> fromFile(GpuContext& ctx, const std::string& path) {
    const std::optional<json> file = readCalibration(path);
    if (!file || !isCalibration(*file) || !isCompleteCalibration(*file))
        throw UsageError("--calibration: " + path + " is not a complete triptych calibration");
    const json& key = (*file)["key"]; // complete: device and driver are strings
    if (key["device"] != ctx.info.name || key["driver"] != ctx.info.driver)
        throw UsageError("--calibration: " + path + " was measured on " + key["device"].get<std::string>() +
                         ", not on " + ctx.info.name);
    return usable(*file, path);
}

} // namespace

json calibrationKey(const GpuContext& ctx, bool quick) {
    return {{"device", ctx.info.name}, {"driver", ctx.info.driver}, {"type", ctx.info.type},
            {"build_fnv1a64", buildHash()}, {"quick", quick}};
}

std::string cachedCalibrationPath(const json& key) {
    const std::string dir = userCacheDir("calibration");
    if (dir.empty()) return {};
    Fnv1a64 h;
    h.text(key.dump());
    return dir + "/" + h.hex() + ".json";
}

json measureCalibration(GpuContext& ctx, const json& key, const std::string& path, uint32_t repeats,
                        const std::vector<std::string>& command) {
    const bool quick = key["quick"].get<bool>();
    std::fprintf(stderr, "triptych: calibrating %s (%s), %u repeats after a warm-up%s\n", ctx.info.name.c_str(),
                 ctx.info.driver.c_str(), repeats, quick ? ", quick (small working sets)" : "");
    CalibrationOptions co;
    co.quick = quick;
    co.repeats = repeats;
    co.progress = [](const std::string& line) { std::fprintf(stderr, "triptych: %s\n", line.c_str()); };
    const std::vector<Ceiling> ceilings = measureCeilings(ctx, co); // measured_at: when they were done
    const json file = calibrationJson(key, utcNow(), repeats, command, ceilings);
    if (const fs::path parent = fs::path(path).parent_path(); !parent.empty()) ensureDirectory(parent.string());
    if (Status written = writeCalibration(path, file); !written.ok())
        throw UsageError("calibrate: " + written.error());
    return file;
}

std::string calibrationOptionHelp() {
    return "The device's measured ceilings that every pass is placed against (docs/efficiency.md): "
           "'auto' uses this device's file from 'triptych calibrate' when there is one (else the "
           "efficiency is left out, saying so), 'measure' measures and caches it when absent or "
           "stale (about 40 s on lavapipe, 1 s on a GPU), 'none' leaves it out, or a calibration FILE "
           "of this device";
}

void checkCalibrationOption(const std::string& option) {
    if (option == "auto" || option == "none" || option == "measure") return;
    if (!fs::exists(option))
        throw UsageError("--calibration: " + option + " does not exist (auto, none, measure or a calibration file)");
}

std::shared_ptr<const RunCalibration> loadRunCalibration(GpuContext& ctx, const std::string& option,
                                                         bool passStatistics) {
    if (option == "none") return unavailable("--calibration none");
    if (!passStatistics)
        return unavailable("--pass-statistics off: placing a pass needs its pipeline statistics");
    if (option != "auto" && option != "measure") return fromFile(ctx, option);
    const json key = calibrationKey(ctx, false);
    const std::string path = cachedCalibrationPath(key);
    if (path.empty()) return unavailable("no cache folder (neither XDG_CACHE_HOME nor HOME): give --calibration FILE");
    std::string why = "absent";
    if (const std::optional<json> file = readCalibration(path))
        if (reusableCalibration(*file, key, why)) return usable(*file, path);
    if (option == "auto")
        return unavailable("no calibration of " + ctx.info.name + " for this build (" + why +
                           "): 'triptych calibrate' measures it, or --calibration measure");
    return usable(measureCalibration(ctx, key, path, 7, {"triptych", "--calibration", "measure"}), path);
}

std::shared_ptr<const CeilingRates> ceilingsOf(const RunCalibration& cal) {
    return cal.available ? std::make_shared<const CeilingRates>(cal.rates) : nullptr;
}

std::string efficiencyNote(const RunResult& run, const std::string& pass) {
    if (!run.efficiency) return {};
    if (pass == "frame")
        return ", passes at their ceilings: " + std::to_string(int(run.efficiency->percent + 0.5)) + "%";
    const PassEfficiency* p = run.efficiency->placed(pass);
    return p ? ", " + std::to_string(int(p->percent + 0.5)) + "% of " + p->bound.limit + " (" + p->bound.ceiling + ")"
             : std::string();
}

json calibrationUseJson(const RunCalibration& cal) {
    if (!cal.available) return {{"available", false}, {"why", cal.why}};
    json ceilings = json::object(); // medians in calibrate's units (GB/s, GFLOP/s, ...)
    for (const auto& [name, rate] : cal.rates)
        ceilings[name] = rate / 1e9;
    return {{"available", true}, {"path", cal.path}, {"key", cal.key}, {"measured_at", cal.measuredAt},
            {"ceilings", ceilings}};
}

} // namespace tp::cli
