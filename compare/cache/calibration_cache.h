#pragma once
// The calibration cache (docs/efficiency.md): a device's calibration file (its format, read and
// written: core/calibrate/calibration_file.h) kept in the user's cache folder, keyed by device,
// driver, triptych build and mode; measured by `triptych calibrate` or --calibration measure, and
// what render, compare and sweep place every pass against (--calibration).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/calibrate/calibration.h"
#include "core/calibrate/calibration_file.h"
#include "core/calibrate/efficiency.h"
#include "core/runner/frame_runner.h"

namespace tp {
class GpuContext;
}

namespace tp::cli {

nlohmann::json calibrationKey(const GpuContext& ctx, bool quick);
// The file a key lives in within the user's cache folder; empty without a cache folder.
std::string cachedCalibrationPath(const nlohmann::json& key);
// Measures this device (progress on stderr) and writes the file to `path`.
nlohmann::json measureCalibration(GpuContext& ctx, const nlohmann::json& key, const std::string& path,
                                  uint32_t repeats, const std::vector<std::string>& command);

// What a run places its passes against: the ceilings, or why there are none.
struct RunCalibration {
    bool available = false;
    std::string why;  // when not available: one line
    std::string path; // the file read
    nlohmann::json key;
    std::string measuredAt;
    CeilingRates rates;
};

// --calibration: "auto" (the cached file of this device and build when there is one), "none",
// "measure" (the cached file, measured and cached when absent or stale), or a FILE (refused
// with one line unless it is a complete calibration of this device and driver).
// passStatistics false (--pass-statistics off): none, as placing a pass needs its counts.
std::shared_ptr<const RunCalibration> loadRunCalibration(GpuContext& ctx, const std::string& option,
                                                         bool passStatistics = true);
// The option's help text.
std::string calibrationOptionHelp();
// Checks the option's form before any GPU work (a FILE must exist).
void checkCalibrationOption(const std::string& option);

// The rates a run places its passes against; null when the calibration is not available.
std::shared_ptr<const CeilingRates> ceilingsOf(const RunCalibration& cal);
// ", 42% of raster (rop_colour)" for a pass the run placed; empty otherwise.
std::string efficiencyNote(const RunResult& run, const std::string& pass);

// report.json's and render.json's "calibration": the file used, or why there is none.
nlohmann::json calibrationUseJson(const RunCalibration& cal);

} // namespace tp::cli
