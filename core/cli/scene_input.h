#pragma once
// The scene a command or the viewer renders, from its SceneOptions: the file or built-in
// scene, its camera (or --camera's), its lights (the file's, a lights file's, generated).
#include <string>

#include "core/cli/options.h"
#include "core/scene/lights.h"
#include "core/scene/scene.h"

namespace tp::cli {

// Where the camera of a run came from, for report.json / render.json / sweep.json.
struct CameraSource {
    // "scene": a built-in scene's own camera; "gltf": the file's camera `gltfCamera`;
    // "framed": a glTF with no usable camera, framed from its bounds; "file": --camera `path`.
    std::string kind = "scene";
    int gltfCamera = -1;
    std::string path;
};

// Reads --camera's file; UsageError naming the option and the file when it is unusable.
// Commands call it (through loadScene, or first thing where the scene loads late) before
// any GPU work.
Camera readCameraOption(const std::string& path);
// Loads or builds the scene, replaces its camera when --camera is given and sets its lights;
// warnings go to stderr. `cameraSource`, if given, says where the camera came from.
Scene loadScene(const SceneOptions& o, CameraSource* cameraSource = nullptr);
// The light generator's options from `o` (UsageError on a bad one): the viewer regenerates
// the lights of a loaded scene when only they change.
LightGenOptions generatorOptions(const SceneOptions& o);

} // namespace tp::cli
