#pragma once
// Hashes that identify a scene in report.json, so a run can be repeated and a changed input
// shows: the bytes of a glTF file and of every file it references, and the loaded scene data
// (for built-in scenes, which code generates, the only way a generator change shows).
// All are FNV-1a 64, written as 16 hex digits.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace tp::cli {

// FNV-1a 64, the hash of every function here (and of the reference cache's entries).
class Fnv1a64 {
  public:
    void bytes(const void* data, size_t n) {
        const auto* p = static_cast<const uint8_t*>(data);
        for (size_t i = 0; i < n; ++i) {
            h_ ^= p[i];
            h_ *= 1099511628211ull;
        }
    }
    // Length first, so ("ab","c") and ("a","bc") differ.
    void text(const std::string& s) {
        u64(s.size());
        bytes(s.data(), s.size());
    }
    void u64(uint64_t v) { bytes(&v, sizeof v); }
    void f32(float v) { bytes(&v, sizeof v); }
    // Arrays of floats / integers / glm vectors (tightly packed, no padding).
    template <class T> void array(const std::vector<T>& v) {
        u64(v.size());
        bytes(v.data(), v.size() * sizeof(T));
    }
    std::string hex() const {
        char out[17];
        std::snprintf(out, sizeof out, "%016llx", (unsigned long long)h_);
        return out;
    }

  private:
    uint64_t h_ = 1469598103934665603ull; // offset basis
};

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
