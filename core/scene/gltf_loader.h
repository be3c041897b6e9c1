#pragma once
// glTF 2.0 (.gltf / .glb) loader on tinygltf. Node transforms are flattened into world-space
// vertices; missing normals and tangents are generated; problems become one-line errors
// that name the file; a missing texture becomes a placeholder with a warning.
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "core/util/result.h"

namespace tp {

struct GltfLoadOptions {
    // Warnings (missing texture, ignored extension, ...) are appended here, one line each.
    std::vector<std::string>* warnings = nullptr;
    // Missing NORMALs: the spec's flat normals (false: vertices are split per triangle) or
    // area-weighted smooth ones (true).
    bool smoothMissingNormals = false;
    // Refuse, instead of repairing, NaN/infinite normals, tangents, uvs and colours and uvs
    // past 2^112, where texture addressing overflows on the GPU (Scene::repairs lists what was
    // repaired; zero-length normals and tangents always are).
    bool strict = false;
    // Set to the index (into the file's "cameras") of the camera Scene::camera was taken
    // from, or -1 when the file has no usable one and the camera frames the bounds: reports
    // say where their view came from.
    int* cameraIndex = nullptr;
};

Result<Scene> loadGltf(const std::string& path, const GltfLoadOptions& options = {});

} // namespace tp
