#pragma once
// Reading a calibration file (`triptych.calibration/1`, written by `triptych calibrate`) for
// its ceilings: what the viewer places passes against. The cache, its keys and the writing are
// compare/cache/calibration_cache.h.
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "core/calibrate/efficiency.h"
#include "core/util/result.h"

namespace tp {

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
