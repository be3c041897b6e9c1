#pragma once
// triptych sweep: every combination of light count, resolution, MSAA and the pipeline knobs
// through the selected pipelines, the reference once per (light count, resolution, MSAA);
// sweep.csv, sweep.json and sweep.html (docs/report.md). Exposed for the tests, which set
// values the CLI would refuse.
#include <map>
#include <string>
#include <vector>

#include "compare/cli_common.h"

namespace tp::cli {

struct SweepOptions {
    SceneOptions scene; // lightCount is ignored: `lights` lists the counts
    DeviceOptions device;
    // Comma-separated lists.
    std::string lights = "16,64,256", res = "320x180", msaa = "1";
    // Every registered knob by name: a comma-separated list for a sweepable knob (each value
    // is run only by the pipelines that read it), one value for the others. Missing: default.
    std::map<std::string, std::string> knobs;
    std::string pipelines; // empty: every registered one
    std::string out = "sweep";
    int frames = 2, warmup = 1;
    int referenceFrames = 1;   // timed reference frames, no warm-up; 0: no reference, no errors
    float flipDistance = 0.7f; // FLIP's viewing distance, metres (compare/flip_measure.h)
    // Under MSAA, the reference also with --reference-msaa center (as many frames), and the
    // error against it beside the error against the supersampled one.
    bool centerReference = true;
    std::string referenceCache; // --reference-cache (compare/reference_cache.h)
    bool noReferenceCache = false;
    std::vector<std::string> commandLine; // recorded in sweep.json
};

// The sweep's options and their help texts.
void addSweepOptions(CLI::App& cmd, SweepOptions& o);

// Exit codes: 0 every run ok; 3 validation messages (with --validate; in sweep.json); 5 the
// files were written but a run failed (recorded in them).
// Bad input throws UsageError before anything is rendered.
int runSweep(const SweepOptions& o);

} // namespace tp::cli
