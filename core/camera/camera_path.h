#pragma once
// Camera paths (docs/camera_paths.md): the views a run renders one after another, read from
//  a) a JSON file of keyframed camera bookmarks,
//       {"schema":"triptych.camera_path/1","frames":N,"interpolation":"linear"|"catmull-rom",
//        "keys":[<triptych.camera/1 objects (core/camera/camera_file.h)>, ...]}
//     each key may carry a "time" (all keys or none; strictly increasing; default 0, 1, 2, ...);
//     the N views are sampled at even times over [first key's time, last key's time]
//     (N = 1: the first key). Position and target follow the interpolation (catmull-rom:
//     centripetal, see camera_path.cpp); up, yfov, znear and zfar are linear;
//  b) a glTF file (.gltf/.glb) with an animated camera: the first node of the default scene
//     that has a perspective camera and whose translation or rotation is animated (on the
//     node or an ancestor), sampled at `gltfFrames` even times over that animation's range.
// A view at a key's time (JSON) or a keyframe's time (glTF) is that key's camera exactly.
// Every view returned passes cameraFromJson's checks; a path that yields an invalid view is
// refused with one line that names the file and the view's index.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/scene/scene.h"
#include "core/util/result.h"

namespace tp {

inline constexpr const char* kCameraPathSchema = "triptych.camera_path/1";
inline constexpr uint32_t kDefaultGltfPathFrames = 120;
// Views a path may ask for: far more than any run renders (at a frame a second, 28 hours),
// and each is checked as a camera file is, so a typo such as 1e9 must not hang or exhaust
// memory.
inline constexpr uint32_t kMaxPathFrames = 100000;

enum class Interpolation { Linear, CatmullRom };

const char* interpolationName(Interpolation interpolation); // "linear", "catmull-rom"

// Views sampled from keys at `times` (strictly increasing, one per key; a single key gives
// `frames` copies of it). `where` prefixes errors ("FILE"); they name the view index.
Result<std::vector<Camera>> sampleCameraPath(const std::vector<Camera>& keys,
                                             const std::vector<double>& times, uint32_t frames,
                                             Interpolation interpolation, const std::string& where);

// A parsed triptych.camera_path/1 object, sampled.
Result<std::vector<Camera>> cameraPathFromJson(const nlohmann::json& j, const std::string& where);

// A .gltf/.glb (by extension, any case) is read as (b), anything else as (a). `gltfFrames` is
// used for glTF only (a JSON path names its own frame count).
Result<std::vector<Camera>> readCameraPath(const std::string& path,
                                           uint32_t gltfFrames = kDefaultGltfPathFrames);

// The JSON form of a path through `keys` at the default times (what the viewer saves from
// its bookmarks); reads back, through cameraPathFromJson, as the views sampled from them.
nlohmann::json cameraPathToJson(const std::vector<Camera>& keys, uint32_t frames,
                                Interpolation interpolation);
// Pretty-printed, written through a temporary name and a rename.
Status writeCameraPath(const std::string& path, const std::vector<Camera>& keys, uint32_t frames,
                       Interpolation interpolation);

// (b) alone: the camera path of a glTF file.
Result<std::vector<Camera>> readGltfCameraPath(const std::string& path, uint32_t frames);

} // namespace tp
