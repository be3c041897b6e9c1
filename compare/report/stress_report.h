#pragma once
// stress.json (schema "triptych.stress/2", docs/stress.md) and stress.html (one offline
// page built from stress.json and the PNGs beside it, like compare's report.html).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/measure/stress_case.h"
#include "core/gpu/context.h"

namespace tp::cli {

// commandLine: argv as given (stress.json repeats the run).
nlohmann::json stressJson(const std::vector<std::string>& commandLine, const GpuContext& ctx,
                          const std::vector<StressCaseResult>& results,
                          const std::vector<std::string>& validationMessages);

// PNGs named in the cases' "files" are read from outDir; fails naming an unreadable one.
Result<std::string> stressHtml(const nlohmann::json& report, const std::string& outDir);

} // namespace tp::cli
