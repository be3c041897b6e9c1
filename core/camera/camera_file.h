#pragma once
// Camera bookmarks: a view a user found (in the viewer, or by hand) saved as a small JSON file
// that `render`, `compare` and `sweep` take with --camera, so the view can be reported and
// repeated. report.json's "camera" object is written by cameraToJson, so it is itself a valid
// camera file.
//
// The format, all keys required, no others allowed (a misspelt key must not be ignored):
//   {"schema":"triptych.camera/1","position":[x,y,z],"target":[x,y,z],"up":[x,y,z],
//    "yfov_degrees":f,"znear":f,"zfar":f}
// Units are the scene's (metres); zfar 0 = an infinite far plane (reverse-Z). `up` need not be
// unit length or orthogonal to the view direction, only not parallel to it.
#include <string>

#include <nlohmann/json.hpp>

#include "core/scene/scene.h"
#include "core/util/result.h"

namespace tp {

inline constexpr const char* kCameraSchema = "triptych.camera/1";

nlohmann::json cameraToJson(const Camera& camera);
// Checks everything a renderer would trip on (non-finite numbers, position == target, up
// parallel to the view direction, yfov outside (0, 180) degrees, znear <= 0, zfar neither 0
// nor beyond znear); the error is one line that names `where` (a file path, or e.g.
// "report.json camera").
Result<Camera> cameraFromJson(const nlohmann::json& j, const std::string& where);
Result<Camera> readCameraFile(const std::string& path);
// Pretty-printed (one key a line), written through a temporary name and a rename.
Status writeCameraFile(const std::string& path, const Camera& camera);

} // namespace tp
