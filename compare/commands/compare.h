#pragma once
// triptych compare: the reference and every selected pipeline on ONE uploaded scene, their
// images, difference maps, error metrics, timings and memory, written as report.json and a
// self-contained report.html (docs/report.md). Exposed for the tests, which set knobs the
// CLI would refuse.
#include <string>
#include <vector>

#include "compare/commands/path_options.h"
#include "core/cli/cli_common.h"
#include "core/renderer/settings.h"

namespace tp::cli {

struct CompareOptions {
    SceneOptions scene;
    DeviceOptions device;
    ViewOptions view;
    std::string pipelines; // comma-separated; empty = every registered one but the reference
    std::string out = "out";
    int frames = 3;
    int warmup = 1;
    std::string exposure = "auto"; // of every PNG; "auto" is taken from the reference
    float flipDistance = 0.7f;     // FLIP's viewing distance, metres (compare/measure/flip_measure.h)
    RenderSettings knobs;
    // Under MSAA: also render the reference with --reference-msaa center and measure every
    // pipeline against it (one more reference render; --no-center-reference turns it off).
    bool centerReference = true;
    // The reference cache's folder (compare/cache/reference_cache.h): --reference-cache DIR, the
    // user's cache folder by default; --no-reference-cache turns it off.
    std::string referenceCache;
    bool noReferenceCache = false;
    std::string calibration = "auto"; // --calibration (compare/cache/calibration_cache.h)
    bool passStatistics = true;       // --pass-statistics (RenderSettings::passStatistics)
    // --camera-path / --light-motion (compare/measure/path_run.h): the path first, then the full report
    // at its worst view.
    PathOptions path;
    std::vector<std::string> commandLine; // recorded in report.json
};

// Exit codes: 0 all ran; 3 validation messages (with --validate); 5 the report was written
// but a pipeline failed (recorded in it). Bad input and a failed reference throw UsageError.
int runCompare(const CompareOptions& o);

} // namespace tp::cli
