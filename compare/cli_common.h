#pragma once
// What every triptych command shares: scene and light options, the device, parsing and
// validation of user input into one-line errors.
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/gpu/context.h"
#include "core/image/image.h"
#include "core/render/frame_runner.h"
#include "core/render/renderer.h"
#include "core/render/settings.h"
#include "core/scene/lights.h"
#include "core/scene/scene.h"
#include "core/util/result.h"

namespace tp::cli {

// A user error: printed as "triptych: <message>", exit code 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct SceneOptions {
    std::string scene;        // path to .gltf/.glb, or builtin:NAME; empty = builtin:courtyard
    std::string lightsFile;   // lights JSON (replaces generated lights)
    int lightCount = 128;
    uint64_t seed = 1;
    std::string lightTypes = "point"; // e.g. "point", "point,spot", "point:3,spot:1,directional:0"
    std::string lightRadius;  // "MIN,MAX" in scene units; empty = from the scene bounds
    std::string lightIntensity; // "MIN,MAX" candela; empty = from the radius
    bool dropSceneLights = false;
    bool strict = false; // glTF: refuse non-finite attributes instead of repairing them
    std::string cameraFile; // --camera: a camera bookmark replacing the scene's camera
};

// Where the camera of a run came from, for report.json / render.json / sweep.json.
struct CameraSource {
    // "scene": a built-in scene's own camera; "gltf": the file's camera `gltfCamera`;
    // "framed": a glTF with no usable camera, framed from its bounds; "file": --camera `path`.
    std::string kind = "scene";
    int gltfCamera = -1;
    std::string path;
};

struct DeviceOptions {
    std::string device;
    bool validate = false;
};

struct ViewOptions {
    std::string resolution = "320x180";
    int msaa = 1;
};

void addSceneOptions(CLI::App& app, SceneOptions& o);
// --seed with its check (CLI11 alone would wrap "-1" to 2^64-1); for commands that add the
// scene options one by one (sweep).
CLI::Option* addSeedOption(CLI::App& app, uint64_t& seed);
// --strict (SceneOptions::strict), likewise.
CLI::Option* addStrictFlag(CLI::App& app, bool& strict);
void addDeviceOptions(CLI::App& app, DeviceOptions& o);
void addViewOptions(CLI::App& app, ViewOptions& o);
// One option per knob of the registered renderers (core/render/knobs.h), bound into
// `values` (RenderSettings::knobs) and set to the knob's default; checked by checkKnobs.
// sweep: a sweepable knob takes a comma-separated list.
void addKnobOptions(CLI::App& app, std::map<std::string, std::string>& values, bool sweep = false);
// A knob's help text: what it does, its allowed values, who reads it, whether it matters
// only under MSAA (list: sweep's comma-separated form).
std::string knobHelp(const KnobReaders& k, bool list);
// Every knob value in `s` against its declaration; UsageError (one line naming the knob and
// its allowed values) on the first bad one. Commands call it before any GPU work.
// sweep: the lists of sweepable knobs are left to runSweep.
void checkKnobs(const std::map<std::string, std::string>& values, bool sweep = false);

// --camera FILE (SceneOptions::cameraFile), for commands that add the scene options one by
// one (sweep).
CLI::Option* addCameraOption(CLI::App& app, std::string& path);
// Reads --camera's file; UsageError naming the option and the file when it is unusable.
// Commands call it (through loadScene, or first thing where the scene loads late) before
// any GPU work.
Camera readCameraOption(const std::string& path);
// Loads or builds the scene, replaces its camera when --camera is given and sets its lights;
// warnings go to stderr. `cameraSource`, if given, says where the camera came from.
Scene loadScene(const SceneOptions& o, CameraSource* cameraSource = nullptr);
std::unique_ptr<GpuContext> createContext(const DeviceOptions& o);
// Resolution and MSAA checked against the device's limits.
// `base` carries the pipeline knobs; the result adds resolution and MSAA.
RenderSettings makeSettings(const ViewOptions& v, const GpuContext& ctx, RenderSettings base = {});

// Creates DIR (and parents); error if it cannot.
void ensureDirectory(const std::string& dir);

// --frames / --warmup bounds shared by the commands that time frames.
void checkFrameCounts(int frames, int warmup);

// --pipelines: the named pipelines in order, without repeats (empty: every registered one
// but the reference, which compare, sweep and stress always render).
std::vector<std::string> selectPipelines(const std::string& list);
// That default as the help texts show it: "forwardplus,deferred,...".
std::string defaultPipelineList();
// Exposure in EV: "auto" (log-average luminance of `image` to 0.18) or a number in [-64, 64].
float parseExposure(const std::string& text, const ImageRGBA& image);
// Warm-up then timed frames, one progress line per frame on stderr prefixed by `label`.
RunOptions progressRunOptions(const std::string& label, int warmup, int frames);

} // namespace tp::cli
