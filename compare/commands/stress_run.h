#pragma once
// triptych stress: every selected case of the catalogue (core/scene/stress_scenes.h) through
// the reference and every registered pipeline, measured against the case's expectations
// (core/renderer/error_model.h and each pipeline's register.cpp), written as images, difference maps,
// stress.json and stress.html (docs/stress.md).
#include <string>
#include <vector>

#include "core/cli/cli_common.h"
#include "compare/measure/stress_case.h"
#include "core/renderer/settings.h"

namespace tp::cli {

struct StressOptions {
    std::string cases;     // comma-separated names; empty = all
    std::string pipelines; // comma-separated; empty = every registered pipeline
    std::string out = "stress";
    DeviceOptions device;
    RenderSettings knobs; // the pipelines' knobs (each case sets resolution and MSAA)
    std::vector<std::string> commandLine;
};

// Exit codes: 0 every case passed; 6 a case failed (its verdicts are in the report);
// 3 validation messages (with --validate). Bad input throws UsageError (2).
int runStress(const StressOptions& o);

} // namespace tp::cli
