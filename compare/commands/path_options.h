#pragma once
// --camera-path, --path-frames and --light-motion of render, compare and sweep
// (docs/camera_paths.md): read and checked before any GPU work into the PathInput a path run
// takes (compare/measure/path_run.h).
#include <optional>
#include <string>

#include "compare/measure/path_run.h"
#include "core/cli/cli_fwd.h"

namespace tp::cli {

struct PathOptions {
    std::string cameraPath;          // empty: no path (a single view, unless lights move)
    uint32_t frames = 120;           // views of a glTF camera path, or of moving lights alone
    std::string lightMotion = "none"; // MODE[:SPEED]
};

void addPathOptions(CLI::App& app, PathOptions& o);
// No path and no light motion: nullopt (a run of one view, as before). Otherwise the views
// (the path's, or `frames` copies of the scene's camera when only the lights move) and the
// lights of each view, seeded with `seed`. UsageError: one line.
std::optional<PathInput> loadPathInput(const PathOptions& o, const Scene& scene, uint64_t seed);

} // namespace tp::cli
