#pragma once
// The calibration file (`triptych.calibration/1`, docs/efficiency.md), both ways: its JSON as
// `triptych calibrate` writes it, and its reading by every command that places passes against
// the device's ceilings (render, compare, sweep, the viewer). Where a file lives, what it is
// keyed by and when one is measured are the callers' (compare/cache/calibration_cache.h).
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/calibrate/calibration.h"
#include "core/calibrate/efficiency.h"
#include "core/util/result.h"

namespace tp {

constexpr const char* kCalibrationSchema = "triptych.calibration/1";

// The file: `key` (an object with at least "device" and "driver"), when it was measured (UTC,
// ISO 8601), the command that measured it and its ceilings in calibrate's units.
nlohmann::json calibrationJson(const nlohmann::json& key, const std::string& measuredAt, uint32_t repeats,
                               const std::vector<std::string>& command, const std::vector<Ceiling>& ceilings);
// Writes `file` to `path` (whose folder exists), as `triptych calibrate` leaves it.
Status writeCalibration(const std::string& path, const nlohmann::json& file);

// Absent: nothing; else parsed (a value that is not a calibration when it does not parse).
std::optional<nlohmann::json> readCalibration(const std::string& path);
bool isCalibration(const nlohmann::json& file);
// Every field the readers read, of the types they read them as.
bool isCompleteCalibration(const nlohmann::json& file);
// `file` when it is a complete calibration of `key` with this build's ceilings; else nothing,
// with `why` saying what was wrong.
std::optional<nlohmann::json> reusableCalibration(const nlohmann::json& file, const nlohmann::json& key,
                                                  std::string& why);

// What the viewer places passes against: the file's ceilings and whose they are.
struct CeilingFile {
    std::string path, device, driver, measuredAt;
    CeilingRates rates; // medians in the base unit per second
};

// Error: one line naming the file ("... is not a complete triptych calibration").
Result<CeilingFile> readCeilingFile(const std::string& path);
// The medians of a parsed calibration's "ceilings" (calibrate's units are G/s: x 1e9); nothing
// when an entry lacks its name or median.
std::optional<CeilingRates> ceilingRatesOf(const nlohmann::json& file);

} // namespace tp
