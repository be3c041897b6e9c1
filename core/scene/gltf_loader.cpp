// glTF 2.0 loader: the order of the steps. Files, the GLB container, the JSON and every URI
// are checked first (gltf_files.cpp); tinygltf parses with file access confined to the
// scene's folder; every accessor (gltf_accessors.cpp) and the node hierarchy
// (gltf_nodes.cpp) are checked; materials (gltf_materials.cpp) and the default scene's meshes
// (gltf_geometry.cpp) are built; the camera comes last, from the bounds.
#include "core/scene/gltf_loader.h"

#include <cstring>
#include <filesystem>

#include "core/scene/gltf_internal.h"

namespace tp {
namespace {

namespace fs = std::filesystem;
using namespace gltf;

const char* const kTooLarge = "the scene is absurdly large (over 2^28 vertices or indices once "
                              "every node's meshes are placed)";

Status buildMeshes(const tinygltf::Model& model, const std::vector<Instance>& instances,
                   const GltfLoadOptions& options, Scene& scene, const WarnFn& warn) {
    std::vector<size_t> usesLeft(model.meshes.size(), 0);
    for (const Instance& inst : instances)
        if (inst.mesh >= 0) ++usesLeft[size_t(inst.mesh)];
    std::vector<std::vector<LocalPrimitive>> cache(model.meshes.size());
    const uint32_t materialCount = uint32_t(model.materials.size());
    bool needDefault = scene.materials.empty();
    uint64_t vertices = 0, indices = 0;
    PrimitiveOptions primitiveOptions;
    primitiveOptions.smoothNormals = options.smoothMissingNormals;
    for (const Instance& inst : instances) {
        if (inst.node >= 0) addLight(model, inst, scene, warn);
        if (inst.mesh < 0) continue;
        const tinygltf::Mesh& mesh = model.meshes[size_t(inst.mesh)];
        std::vector<LocalPrimitive>& prims = cache[size_t(inst.mesh)];
        if (prims.empty()) {
            // Before reading: an accessor without a bufferView is zeros of any count, so
            // counts alone could ask for gigabytes.
            uint64_t declared = vertices;
            for (const tinygltf::Primitive& p : mesh.primitives)
                if (auto it = p.attributes.find("POSITION");
                    it != p.attributes.end() && it->second >= 0 &&
                    size_t(it->second) < model.accessors.size())
                    declared += model.accessors[size_t(it->second)].count;
            if (declared > kMaxElements) return Error{kTooLarge};
            prims.resize(mesh.primitives.size());
            for (size_t p = 0; p < prims.size(); ++p) {
                Status s =
                    readPrimitive(model, inst.mesh, int(p), primitiveOptions, prims[p], warn);
                if (!s) return s;
            }
        }
        for (size_t p = 0; p < prims.size(); ++p) {
            const LocalPrimitive& prim = prims[p];
            if (prim.positions.empty()) continue;
            vertices += prim.positions.size();
            indices += prim.indices.size();
            if (vertices > kMaxElements || indices > kMaxElements) return Error{kTooLarge};
            Mesh out;
            out.name = mesh.name.empty() ? "mesh " + std::to_string(inst.mesh) : mesh.name;
            if (prims.size() > 1) out.name.append(1, '#').append(std::to_string(p));
            if (prim.material >= 0 && uint32_t(prim.material) < materialCount) {
                out.material = uint32_t(prim.material);
            } else {
                if (prim.material >= 0)
                    warn(out.name + ": material " + std::to_string(prim.material) +
                         " does not exist; using the default material");
                out.material = materialCount;
                needDefault = true;
            }
            appendTransformed(prim, inst.world, out);
            scene.meshes.push_back(std::move(out));
        }
        if (--usesLeft[size_t(inst.mesh)] == 0) prims = {};
    }
    if (needDefault) {
        Material fallback;
        fallback.name = "default";
        scene.materials.push_back(fallback);
    }
    return {};
}

// Messages quote the file (names, URIs, the JSON parser's last token): control characters
// become spaces and bytes that are not UTF-8 become '?', so a message is one printable line.
std::string printableLine(const std::string& text) {
    std::string out;
    for (size_t i = 0; i < text.size();) {
        const uint8_t c = uint8_t(text[i]);
        size_t length = c < 0x80         ? 1
                        : (c >> 5) == 6  ? 2
                        : (c >> 4) == 14 ? 3
                        : (c >> 3) == 30 ? 4
                                         : 0;
        bool valid = length > 0 && i + length <= text.size();
        for (size_t k = 1; valid && k < length; ++k)
            valid = (uint8_t(text[i + k]) >> 6) == 2;
        if (!valid) {
            out += '?';
            ++i;
        } else if (length == 1) {
            out += c < 0x20 || c == 0x7f ? ' ' : char(c);
            ++i;
        } else {
            out.append(text, i, length);
            i += length;
        }
    }
    return out;
}

Result<Scene> load(const std::string& path, const GltfLoadOptions& options, const WarnFn& warn) {
    std::vector<unsigned char> bytes;
    if (Status s = readFile(path, bytes); !s) return Error{s.error()};
    const fs::path folder = fs::absolute(fs::path(path)).parent_path().lexically_normal();
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext)
        c = char(std::tolower(uint8_t(c)));
    // By extension, or by the GLB magic whatever the extension says.
    const bool binary =
        ext == ".glb" || (bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0);

    std::string_view jsonText(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (binary)
        if (Status s = checkGlb(bytes, jsonText); !s) return Error{s.error()};
    FileAccess access;
    std::vector<std::string> imageProblems;
    if (Status s = prescan(jsonText, folder, binary, access, imageProblems, warn); !s)
        return Error{s.error()};

    // From memory rather than LoadASCIIFromFile/LoadBinaryFromFile: the bytes tinygltf parses
    // are the bytes checked above, read once.
    tinygltf::TinyGLTF loader;
    confine(loader, access);
    tinygltf::Model model;
    std::string err, tinyWarn;
    bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &tinyWarn, bytes.data(),
                                                   unsigned(bytes.size()), folder.string())
                     : loader.LoadASCIIFromString(&model, &err, &tinyWarn,
                                                  reinterpret_cast<const char*>(bytes.data()),
                                                  unsigned(bytes.size()), folder.string());
    if (!ok) {
        std::string line = firstLine(err);
        return Error{"tinygltf: " + (line.empty() ? "cannot load the file" : line)};
    }
    bytes = {};
    imageProblems.resize(model.images.size());
    for (size_t i = 0; i < model.images.size(); ++i)
        if (imageProblems[i].empty() && model.images[i].image.empty())
            imageProblems[i] = "could not be read (" + firstLine(tinyWarn) + ")";

    for (size_t i = 0; i < model.accessors.size(); ++i)
        if (Status s = checkAccessor(model, i); !s) return Error{s.error()};
    std::vector<Instance> instances;
    if (Status s = collectInstances(model, instances); !s) return Error{s.error()};
    Scene scene;
    scene.source = path;
    if (Status s = loadMaterials(model, imageProblems, scene, warn); !s) return Error{s.error()};
    if (Status s = buildMeshes(model, instances, options, scene, warn); !s) return Error{s.error()};
    for (const tinygltf::Node& node : model.nodes)
        if (node.skin >= 0) {
            warn("skins are ignored: skinned meshes are drawn in their bind pose");
            break;
        }
    scene.computeBounds();
    if (scene.triangleCount() == 0)
        return Error{model.meshes.empty() ? "nothing to draw: the file has no meshes"
                                          : "nothing to draw: the scene has no triangles"};
    placeCamera(model, instances, scene);
    return scene;
}

} // namespace

Result<Scene> loadGltf(const std::string& path, const GltfLoadOptions& options) {
    auto warn = [&](const std::string& line) {
        if (options.warnings) options.warnings->push_back(printableLine(path + ": " + line));
    };
    std::string problem;
    try {
        Result<Scene> scene = load(path, options, warn);
        if (scene.ok()) return scene;
        problem = scene.error();
    } catch (const std::bad_alloc&) {
        problem = "out of memory while loading";
    } catch (const std::exception& e) {
        problem = "unexpected failure: " + firstLine(e.what());
    }
    return Error{printableLine(path + ": " + problem)};
}

} // namespace tp
