// FNV-1a 64 hashes of a scene's files and of its loaded data (see scene_hash.h). The scene
// was loaded before these run, so its JSON is known to parse; anything odd here only makes
// the hash cover less, and says so in FileHashes::missing.
#include "compare/cache/scene_hash.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

namespace tp::cli {
namespace {

namespace fs = std::filesystem;

std::string readAll(const fs::path& path, bool& ok) {
    std::ifstream in(path, std::ios::binary);
    ok = bool(in);
    return ok ? std::string(std::istreambuf_iterator<char>(in), {}) : std::string();
}

// The glTF's JSON: the whole .gltf file, or the first chunk of a .glb.
std::string gltfJson(const std::string& bytes) {
    if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0) return bytes;
    uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4); // little-endian hosts only, like the loader
    return bytes.substr(20, std::min<size_t>(length, bytes.size() - 20));
}

std::string decodeUri(const std::string& s) { // as the loader decodes it (gltf_files.cpp)
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '%' && i + 2 < s.size()) {
            out += char(std::stoi(s.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else
            out += s[i] == '+' ? ' ' : s[i];
    }
    return out;
}

std::vector<fs::path> referencedFiles(const std::string& json, const fs::path& folder) {
    std::vector<fs::path> files;
    nlohmann::json root = nlohmann::json::parse(json, nullptr, false);
    if (!root.is_object()) return files;
    for (const char* key : {"buffers", "images"}) {
        if (!root.contains(key) || !root[key].is_array()) continue;
        for (const nlohmann::json& item : root[key]) {
            if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) continue;
            const std::string uri = item["uri"];
            if (uri.rfind("data:", 0) == 0) continue;
            try {
                files.push_back((folder / decodeUri(uri)).lexically_normal());
            } catch (const std::exception&) { // a malformed %XX: nothing to hash
            }
        }
    }
    return files;
}

void hashCameraInto(Fnv1a64& h, const Camera& c) {
    for (float f : {c.position.x, c.position.y, c.position.z, c.target.x, c.target.y, c.target.z,
                    c.up.x, c.up.y, c.up.z, c.yfov, c.znear, c.zfar})
        h.f32(f);
}

} // namespace

FileHashes hashSceneFiles(const std::string& path) {
    FileHashes result;
    bool ok = false;
    const std::string scene = readAll(path, ok);
    if (!ok) return result;
    Fnv1a64 h;
    std::vector<fs::path> files = {fs::path(path)};
    for (const fs::path& f : referencedFiles(gltfJson(scene), fs::path(path).parent_path()))
        files.push_back(f);
    for (size_t i = 0; i < files.size(); ++i) {
        const std::string bytes = i == 0 ? scene : readAll(files[i], ok);
        result.files.push_back(files[i].string());
        // The name as the JSON gives it (relative to the scene), so a moved folder hashes the same.
        h.text(i == 0 ? files[i].filename().string()
                      : files[i].lexically_relative(files[0].parent_path()).string());
        if (!ok) {
            result.missing.push_back(files[i].string());
            h.text("<missing>");
            continue;
        }
        h.text(bytes);
    }
    result.hash = h.hex();
    return result;
}

std::string hashSceneContent(const Scene& scene) {
    Fnv1a64 h;
    h.u64(scene.meshes.size());
    for (const Mesh& m : scene.meshes) {
        h.text(m.name);
        h.array(m.positions);
        h.array(m.normals);
        h.array(m.tangents);
        h.array(m.uvs);
        h.array(m.colors);
        h.array(m.indices);
        h.u64(m.material);
    }
    h.u64(scene.materials.size());
    for (const Material& m : scene.materials) {
        h.text(m.name);
        h.bytes(&m.baseColorFactor, sizeof m.baseColorFactor);
        for (float f : {m.metallicFactor, m.roughnessFactor, m.emissiveFactor.x, m.emissiveFactor.y,
                        m.emissiveFactor.z, m.normalScale, m.occlusionStrength, m.alphaCutoff})
            h.f32(f);
        for (int64_t v : {int64_t(m.alphaMode), int64_t(m.doubleSided), int64_t(m.baseColorTexture),
                          int64_t(m.metallicRoughnessTexture), int64_t(m.normalTexture),
                          int64_t(m.occlusionTexture), int64_t(m.emissiveTexture)})
            h.u64(uint64_t(v));
    }
    h.u64(scene.textures.size());
    for (const Texture& t : scene.textures) {
        h.text(t.name);
        h.u64(t.width);
        h.u64(t.height);
        h.u64(t.srgb);
        h.array(t.rgba8);
    }
    hashCameraInto(h, scene.camera);
    for (float f : {scene.ambient.x, scene.ambient.y, scene.ambient.z})
        h.f32(f);
    return h.hex();
}

std::string hashCamera(const Camera& camera) {
    Fnv1a64 h;
    hashCameraInto(h, camera);
    return h.hex();
}

std::string hashLights(const std::vector<Light>& lights) {
    Fnv1a64 h;
    h.u64(lights.size());
    for (const Light& l : lights) {
        h.u64(uint64_t(l.type));
        for (float f : {l.position.x, l.position.y, l.position.z, l.direction.x, l.direction.y,
                        l.direction.z, l.color.x, l.color.y, l.color.z, l.intensity, l.range,
                        l.innerConeAngle, l.outerConeAngle})
            h.f32(f);
    }
    return h.hex();
}

} // namespace tp::cli
