#pragma once
// Hashes that identify a scene in report.json, so a run can be repeated and a changed input
// shows: the bytes of a glTF file and of every file it references, and the loaded scene data
// (for built-in scenes, which code generates, the only way a generator change shows).
// All are FNV-1a 64, written as 16 hex digits.
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace tp::cli {

struct FileHashes {
    std::string hash;               // over each file in `files` order: its name, size and bytes
    std::vector<std::string> files; // the scene file, then buffers, then images (paths as resolved)
    std::vector<std::string> missing; // referenced files that could not be read (hashed as absent)
};

// A .gltf/.glb file and the external buffers and images its JSON references (data: URIs are
// part of the file's bytes already). Empty hash when the scene file itself cannot be read.
FileHashes hashSceneFiles(const std::string& path);

// Geometry (every mesh attribute and index), materials, textures (texels), camera and ambient,
// in a fixed field order; lights are not included (see hashLights). The camera is the one the
// run used: a --camera file's when given, so a changed view changes this hash.
std::string hashSceneContent(const Scene& scene);
// The camera alone, every field bit for bit: tells "same scene, other view" from "other scene"
// (the file and content hashes cannot: the file hash never sees --camera, the content hash
// sees both).
std::string hashCamera(const Camera& camera);
std::string hashLights(const std::vector<Light>& lights);

} // namespace tp::cli
