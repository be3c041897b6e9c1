#pragma once
// The options every triptych command shares, the viewer's `view` among them: scene and light
// options, the device, resolution and MSAA, the pipelines' knobs, and their checks into
// one-line errors. Below both compare/ and viewer/ (docs/architecture.md, "Layers").
#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/cli/cli_fwd.h"

#include "core/gpu/context.h"
#include "core/renderer/renderer.h"
#include "core/renderer/settings.h"

namespace tp::cli {

// A user error: printed as "triptych: <message>", exit code 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct SceneOptions {
    std::string scene;      // path to .gltf/.glb, or builtin:NAME; empty = builtin:courtyard
    std::string lightsFile; // lights JSON (replaces generated lights)
    int lightCount = 128;
    uint64_t seed = 1;
    std::string lightTypes = "point"; // e.g. "point", "point,spot", "point:3,spot:1,directional:0"
    std::string lightRadius;          // "MIN,MAX" in scene units; empty = from the scene bounds
    std::string lightIntensity;       // "MIN,MAX" candela; empty = from the radius
    bool dropSceneLights = false;
    bool strict = false;    // glTF: refuse non-finite attributes instead of repairing them
    std::string cameraFile; // --camera: a camera bookmark replacing the scene's camera
};

struct DeviceOptions {
    std::string device;
    bool validate = false;
};

struct ViewOptions {
    std::string resolution = "320x180";
    int msaa = 1;
    std::string shadows = "none"; // --shadows N|all|none
    int shadowBudgetMb = 256;     // --shadow-budget MB
    std::string shadowCache = "on"; // --shadow-cache on|off
};

void addSceneOptions(CLI::App& app, SceneOptions& o);
// --seed with its check (CLI11 alone would wrap "-1" to 2^64-1); for commands that add the
// scene options one by one (sweep).
CLI::Option* addSeedOption(CLI::App& app, uint64_t& seed);
// --strict (SceneOptions::strict), likewise.
CLI::Option* addStrictFlag(CLI::App& app, bool& strict);
// --camera FILE (SceneOptions::cameraFile), likewise.
CLI::Option* addCameraOption(CLI::App& app, std::string& path);
void addDeviceOptions(CLI::App& app, DeviceOptions& o);
void addViewOptions(CLI::App& app, ViewOptions& o);
// --pass-statistics on|off, for the commands that time frames (RenderSettings::passStatistics).
CLI::Option* addPassStatisticsOption(CLI::App& app, bool& on);
// One option per knob of the registered renderers (core/renderer/knobs.h), bound into
// `values` (RenderSettings::knobs) and set to the knob's default; checked by checkKnobs.
// sweep: a sweepable knob takes a comma-separated list.
void addKnobOptions(CLI::App& app, std::map<std::string, std::string>& values, bool sweep = false);
// A knob's help text: what it does, its allowed values, who reads it, whether it matters
// only under MSAA (list: sweep's comma-separated form).
std::string knobHelp(const KnobReaders& k, bool list);
// Every knob value in `values` through checkSetting (core/renderer/view_settings.h); UsageError
// (one line naming the knob and its allowed values) on the first bad one. Commands call it
// before any GPU work. sweep: the lists of sweepable knobs are left to runSweep.
void checkKnobs(const std::map<std::string, std::string>& values, bool sweep = false);

std::unique_ptr<GpuContext> createContext(const DeviceOptions& o);
// Resolution and MSAA checked against the device's limits.
// `base` carries the pipeline knobs; the result adds resolution and MSAA.
RenderSettings makeSettings(const ViewOptions& v, const GpuContext& ctx, RenderSettings base = {});

// Every command's exit code 3: after one line on stderr with the number of validation
// messages and the first one; 0 when there were none.
int validationExit(const std::vector<std::string>& messages);

// Creates DIR (and parents); error if it cannot.
void ensureDirectory(const std::string& dir);

// --pipelines: the named pipelines in order, without repeats (empty: every registered one
// but the reference, which compare, sweep and stress always render).
std::vector<std::string> selectPipelines(const std::string& list);
// That default as the help texts show it: "forwardplus,deferred,...".
std::string defaultPipelineList();

} // namespace tp::cli
