#pragma once
// triptych sweep: every combination of light count, resolution, MSAA and the pipeline knobs
// through the selected pipelines, the reference once per (light count, resolution, MSAA);
// sweep.csv, sweep.json and sweep.html (docs/report.md). Exposed for the tests, which set
// values the CLI would refuse.
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/cli/cli_common.h"
#include "compare/commands/path_options.h"

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
    float flipDistance = 0.7f; // FLIP's viewing distance, metres (compare/measure/flip_measure.h)
    // Under MSAA, the reference also with --reference-msaa center (as many frames), and the
    // error against it beside the error against the supersampled one.
    bool centerReference = true;
    std::string referenceCache; // --reference-cache (compare/cache/reference_cache.h)
    bool noReferenceCache = false;
    std::string calibration = "auto"; // --calibration (compare/cache/calibration_cache.h)
    bool passStatistics = true;       // --pass-statistics (RenderSettings::passStatistics)
    // --camera-path / --light-motion: every row's single view is the path's first; each
    // pipeline row also runs the path's timing pass (compare/measure/path_run.h): its percentiles.
    PathOptions path;
    // --shard K/N: only the runs whose index in the unsharded order is K modulo N (0 <= K < N);
    // `triptych merge` puts the shards back together (docs/scale-out.md).
    std::string shard;
    std::vector<std::string> commandLine; // recorded in sweep.json
};

// A sweep's shard: runs i with i % count == index.
struct Shard {
    uint32_t index = 0, count = 1;
    bool owns(size_t run) const { return run % count == index; }
};
// "K/N" (empty: the whole sweep, 0/1); UsageError naming --shard otherwise.
Shard parseShard(const std::string& text);
// What makes shards one sweep (sweep.json's sweep_id_fnv1a64): the device's name and the
// header but for what differs between shards (command line, --out, --device, the shard's
// index, validation messages).
std::string sweepId(nlohmann::json header);

// triptych merge (compare/commands/cmd_merge.cpp): the shards' output folders into `out`. Exit code 0,
// or 5 when a run failed; UsageError (one line) for shards that are not one whole sweep.
int runMerge(const std::vector<std::string>& dirs, const std::string& out);

// The sweep's options and their help texts.
void addSweepOptions(CLI::App& cmd, SweepOptions& o);

// Exit codes: 0 every run ok; 3 validation messages (with --validate; in sweep.json); 5 the
// files were written but a run failed (recorded in them).
// Bad input throws UsageError before anything is rendered.
int runSweep(const SweepOptions& o);

} // namespace tp::cli
