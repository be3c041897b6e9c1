// The options of `triptych sweep`: lists where the sweep varies a setting, single values
// where it does not. Each help text says what the option does, which pipelines read it
// and its default; the knob options come from the registered renderers' schemas.
#include "compare/cache/reference_cache.h"

#include <CLI/CLI.hpp>
#include "compare/commands/sweep.h"

#include "compare/cache/calibration_cache.h"
#include "compare/measure/flip_measure.h"

namespace tp::cli {

Shard parseShard(const std::string& text) {
    if (text.empty()) return {};
    const size_t slash = text.find('/');
    auto bad = [&](const std::string& why) {
        return UsageError("--shard " + text + ": " + why + " (K/N with 0 <= K < N, e.g. 0/4)");
    };
    if (slash == std::string::npos) throw bad("no '/'");
    auto number = [&](const std::string& s) {
        if (s.empty() || s.size() > 6 || s.find_first_not_of("0123456789") != std::string::npos)
            throw bad("'" + s + "' is not a whole number");
        return uint32_t(std::stoul(s));
    };
    Shard shard{number(text.substr(0, slash)), number(text.substr(slash + 1))};
    if (shard.count == 0) throw bad("N must be at least 1");
    if (shard.index >= shard.count) throw bad("K must be below N");
    return shard;
}

void addSweepOptions(CLI::App& cmd, SweepOptions& o) {
    cmd.add_option(
        "scene", o.scene.scene,
        "Scene: a glTF 2.0 file (.gltf/.glb) or builtin:NAME (courtyard, courtyard-small). "
        "Default: the built-in courtyard");
    cmd.add_option("--lights", o.lights,
                   "Comma-separated counts of generated lights (added to the scene's own); one "
                   "uploaded scene "
                   "per count")
        ->capture_default_str();
    cmd.add_option("--res", o.res, "Comma-separated output resolutions WIDTHxHEIGHT")
        ->capture_default_str();
    cmd.add_option("--msaa", o.msaa,
                   "Comma-separated samples per pixel (1, 2, 4, 8 as the device supports)")
        ->capture_default_str();
    addKnobOptions(cmd, o.knobs, true); // a list where the sweep may vary a knob, else one value
    cmd.add_option("--pipelines", o.pipelines,
                   "Comma-separated pipelines to run (default: every registered one); the "
                   "reference runs anyway "
                   "unless --reference-frames 0");
    cmd.add_option("--frames", o.frames,
                   "Timed frames per pipeline run (median/min/max are over these)")
        ->capture_default_str();
    cmd.add_option("--warmup", o.warmup,
                   "Untimed warm-up frames before each pipeline run's timed ones")
        ->capture_default_str();
    cmd.add_option("--reference-frames", o.referenceFrames,
                   "Timed frames of the reference, with no warm-up: it is rendered for its image, "
                   "once per light "
                   "count, resolution and MSAA. 0: no reference, no error figures")
        ->check(CLI::Range(0, 1000))
        ->capture_default_str();
    addFlipDistanceOption(cmd, o.flipDistance);
    addReferenceCacheOptions(cmd, o.referenceCache, o.noReferenceCache);
    cmd.add_option("--calibration", o.calibration, calibrationOptionHelp())->capture_default_str();
    addPassStatisticsOption(cmd, o.passStatistics);
    cmd.add_option("--shard", o.shard,
                   "K/N: run only the runs whose index in the whole sweep's order is K modulo N "
                   "(0 <= K < N), for one of N processes, GPUs or cluster jobs; 'triptych merge' "
                   "combines the N outputs into the sweep.csv, sweep.json and sweep.html of the "
                   "whole sweep (docs/scale-out.md)");
    cmd.add_flag("--no-center-reference{false}", o.centerReference,
                 "Under MSAA, skip the second reference (--reference-msaa center, one more "
                 "reference render per light "
                 "count, resolution and MSAA) and the *_center error columns");
    addSeedOption(cmd, o.scene.seed);
    cmd.add_option("--light-types", o.scene.lightTypes,
                   "Generated light type mix: point, spot, directional with optional weights, e.g. "
                   "point:3,spot:1")
        ->capture_default_str();
    cmd.add_option("--light-radius", o.scene.lightRadius,
                   "MIN,MAX light range in scene units (default: 4%-12% of the scene's diagonal)");
    cmd.add_option("--light-intensity", o.scene.lightIntensity,
                   "MIN,MAX intensity in candela (default: derived from the radius)");
    cmd.add_flag("--no-scene-lights", o.scene.dropSceneLights,
                 "Ignore lights defined in the glTF file");
    addStrictFlag(cmd, o.scene.strict);
    addCameraOption(cmd, o.scene.cameraFile);
    cmd.add_option("--out", o.out,
                   "Output directory (created if missing) for sweep.csv, sweep.json and sweep.html")
        ->capture_default_str();
    addDeviceOptions(cmd, o.device);
    addPathOptions(cmd, o.path);
}

} // namespace tp::cli
