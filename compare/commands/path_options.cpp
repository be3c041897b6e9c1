#include "compare/commands/path_options.h"

#include <memory>

#include <CLI/CLI.hpp>

#include "compare/report/svg_plot.h"
#include "core/camera/camera_path.h"
#include "core/cli/options.h"
#include "core/scene/light_motion.h"

namespace tp::cli {

void addPathOptions(CLI::App& app, PathOptions& o) {
    app.add_option("--camera-path", o.cameraPath,
                   "Render every view of a camera path instead of one view: a "
                   "triptych.camera_path/1 JSON file (keyframed camera bookmarks, a frame count, "
                   "linear or catmull-rom) or a glTF file with an animated camera "
                   "(docs/camera_paths.md). Each pipeline is planned once; per view: frame time, "
                   "view update and error; per run: percentiles and where the pipelines' ranking "
                   "flips")
        ->type_name("FILE");
    app.add_option("--path-frames", o.frames,
                   "Views sampled from a glTF camera path, or rendered at the scene's camera when "
                   "only --light-motion is given (a JSON path names its own count)")
        ->check(CLI::Range(1u, kMaxPathFrames))
        ->capture_default_str();
    app.add_option("--light-motion", o.lightMotion,
                   "Move the lights per view, seeded by --seed: none, orbit or drift, optionally "
                   ":SPEED in scene units per view (default " +
                       formatNumber(kDefaultLightSpeed) +
                       "); with no --camera-path the camera stays and --path-frames views are "
                       "rendered")
        ->capture_default_str();
}

std::optional<PathInput> loadPathInput(const PathOptions& o, const Scene& scene, uint64_t seed) {
    Result<LightMotion> motion = parseLightMotion(o.lightMotion);
    if (!motion) throw UsageError(motion.error());
    if (o.cameraPath.empty() && motion->mode == LightMotion::Mode::None) return std::nullopt;
    PathInput in;
    in.lightMotion = lightMotionToString(*motion);
    if (o.cameraPath.empty()) {
        in.source = "the scene's camera, " + std::to_string(o.frames) + " views";
        in.views.assign(o.frames, scene.camera);
    } else {
        Result<std::vector<Camera>> views = readCameraPath(o.cameraPath, o.frames);
        if (!views) throw UsageError(views.error());
        in.source = o.cameraPath;
        in.views = std::move(*views);
    }
    if (motion->mode != LightMotion::Mode::None) {
        motion->seed = seed;
        auto plan = std::make_shared<const LightMotionPlan>(scene.lights, *motion, scene.bounds);
        in.lightsAt = [plan](uint32_t v) { return plan->at(v); };
    }
    return in;
}

} // namespace tp::cli
