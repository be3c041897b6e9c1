// libFuzzer target: the glTF loader on arbitrary bytes, read as .gltf text or, by its magic, as
// .glb. External files resolve in $TRIPTYCH_FUZZ_FILES (run.sh copies the seeds' buffers and
// small images there). Besides the sanitizers, a loaded scene must hold together and an error
// must be one line: anything else aborts, which libFuzzer reports as a finding.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "core/scene/gltf_internal.h"

namespace {

std::filesystem::path gFolder;

[[noreturn]] void broken(const char* what, const std::string& detail) {
    std::fprintf(stderr, "fuzz_gltf: %s: %s\n", what, detail.c_str());
    std::abort();
}

template <class V> std::string text(const V& v) {
    std::string out;
    for (int k = 0; k < V::length(); ++k)
        out += (k ? "," : "") + std::to_string(v[k]);
    return out;
}

template <class V> bool finite(const V& v) {
    for (int k = 0; k < V::length(); ++k)
        if (!std::isfinite(v[k])) return false;
    return true;
}

void checkScene(const tp::Scene& s) {
    if (s.triangleCount() == 0) broken("loaded", "a scene without triangles");
    for (const tp::Mesh& m : s.meshes) {
        const size_t n = m.positions.size();
        if (m.normals.size() != n || m.tangents.size() != n || m.uvs.size() != n ||
            m.colors.size() != n)
            broken("loaded", m.name + ": attribute arrays of different lengths");
        if (m.indices.size() % 3 != 0) broken("loaded", m.name + ": a partial triangle");
        for (uint32_t i : m.indices)
            if (i >= n) broken("loaded", m.name + ": index past the vertices");
        if (m.material >= s.materials.size()) broken("loaded", m.name + ": no such material");
        // Component by component: a sum of finite values may overflow (a uv of 3.2e38 plus
        // one of 7.3e37 is not a non-finite uv).
        for (size_t i = 0; i < n; ++i)
            if (!finite(m.positions[i]))
                broken("loaded", m.name + ": a position that is not finite");
        // Non-finite normals, tangents and uvs are repaired or refused, never passed on.
        for (size_t i = 0; i < n; ++i)
            if (!finite(m.normals[i]) || !finite(m.tangents[i]) || !finite(m.uvs[i]) ||
                !finite(m.colors[i]))
                broken("loaded", m.name + ": a normal, tangent or uv that is not finite (vertex " +
                                     std::to_string(i) + ": n " + text(m.normals[i]) + " t " +
                                     text(m.tangents[i]) + " uv " + text(m.uvs[i]) + ")");
    }
    for (const tp::Material& m : s.materials)
        for (int32_t t : {m.baseColorTexture, m.metallicRoughnessTexture, m.normalTexture,
                          m.occlusionTexture, m.emissiveTexture})
            if (t != tp::kNoTexture && (t < 0 || size_t(t) >= s.textures.size()))
                broken("loaded", "a material refers to a texture that does not exist");
    for (const tp::Texture& t : s.textures)
        if (t.rgba8.size() != size_t(t.width) * t.height * 4 || t.width == 0 || t.height == 0)
            broken("loaded", t.name + ": texture size and pixels disagree");
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const char* folder = std::getenv("TRIPTYCH_FUZZ_FILES");
    gFolder = folder ? folder : std::filesystem::temp_directory_path().string();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> warnings;
    tp::GltfLoadOptions options;
    options.warnings = &warnings;
    options.smoothMissingNormals = size % 2 == 1; // both normal generators, from the length
    options.strict = size % 4 >= 2;               // repairs and refusals, likewise
    tp::Result<tp::Scene> scene = tp::gltf::loadGltfBytes(
        std::vector<unsigned char>(data, data + size), "fuzz.gltf", gFolder, false, options);
    if (scene.ok())
        checkScene(*scene);
    else if (scene.error().find('\n') != std::string::npos || scene.error().rfind("fuzz.gltf: ", 0))
        broken("error", scene.error());
    for (const std::string& w : warnings)
        if (w.find('\n') != std::string::npos) broken("warning", w);
    return 0;
}
