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

std::string tooLarge() {
    return "the scene is absurdly large (over 2^" + std::to_string(kMaxElementsLog2) +
           " vertices or indices once every node's meshes are placed)";
}

// Before anything is read: the counts the file declares for every placed primitive. Each is a
// lower bound of what building the meshes allocates, so a file that instances one mesh
// thousands of times, or declares zeros by the million, fails here and not after gigabytes.
Status checkDeclaredSize(const tinygltf::Model& model, const std::vector<Instance>& instances) {
    auto count = [&](int accessor) -> uint64_t {
        return accessor >= 0 && size_t(accessor) < model.accessors.size()
                   ? model.accessors[size_t(accessor)].count
                   : 0;
    };
    std::vector<uint64_t> uses(model.meshes.size(), 0);
    for (const Instance& inst : instances)
        if (inst.mesh >= 0) ++uses[size_t(inst.mesh)];
    uint64_t vertices = 0, indices = 0;
    for (size_t m = 0; m < model.meshes.size(); ++m) {
        for (const tinygltf::Primitive& p : model.meshes[m].primitives) {
            if (p.mode >= 0 && p.mode < TINYGLTF_MODE_TRIANGLES) continue; // skipped, not read
            auto it = p.attributes.find("POSITION");
            const uint64_t n = it == p.attributes.end() ? 0 : count(it->second);
            const uint64_t k = p.indices >= 0 ? count(p.indices) : n;
            // Counts are at most 2^24 (checkAccessor) and uses at most the node count: the
            // products cannot overflow 64 bits.
            vertices += n * uses[m];
            indices += k * uses[m];
            if (vertices > kMaxElements || indices > kMaxElements) return Error{tooLarge()};
        }
    }
    return {};
}

// One warning line per repair of an accessor, however many primitives share it (a TEXCOORD_0
// accessor may have two: non-finite values and huge ones).
void noteRepair(SceneRepair r, Scene& scene, const WarnFn& warn) {
    for (const SceneRepair& seen : scene.repairs)
        if (seen.attribute == r.attribute && seen.accessor == r.accessor &&
            seen.problem == r.problem)
            return;
    warn("repaired " + r.attribute + " accessor " + std::to_string(r.accessor) + ": " +
         std::to_string(r.count) + " of " + std::to_string(r.total) + " values were " + r.problem +
         "; " + r.action + " (--strict refuses the file instead)");
    scene.repairs.push_back(std::move(r));
}

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
    primitiveOptions.strict = options.strict;
    for (const Instance& inst : instances) {
        if (inst.node >= 0) addLight(model, inst, scene, warn);
        if (inst.mesh < 0) continue;
        const tinygltf::Mesh& mesh = model.meshes[size_t(inst.mesh)];
        std::vector<LocalPrimitive>& prims = cache[size_t(inst.mesh)];
        if (prims.empty()) {
            prims.resize(mesh.primitives.size());
            for (size_t p = 0; p < prims.size(); ++p) {
                Status s =
                    readPrimitive(model, inst.mesh, int(p), primitiveOptions, prims[p], warn);
                if (!s) return s;
                for (SceneRepair& r : prims[p].repairs)
                    noteRepair(std::move(r), scene, warn);
            }
        }
        for (size_t p = 0; p < prims.size(); ++p) {
            const LocalPrimitive& prim = prims[p];
            if (prim.positions.empty()) continue;
            vertices += prim.positions.size();
            indices += prim.indices.size();
            if (vertices > kMaxElements || indices > kMaxElements) return Error{tooLarge()};
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

Result<Scene> parse(std::vector<unsigned char>& bytes, const std::string& name,
                    const fs::path& folder, bool binaryByName, const GltfLoadOptions& options,
                    const WarnFn& warn) {
    if (bytes.empty()) return Error{"file is empty"};
    if (bytes.size() >= (1ull << 32))
        return Error{"file is over 4 GiB, which tinygltf cannot load"};
    // By extension, or by the GLB magic whatever the extension says.
    const bool binary =
        binaryByName || (bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0);

    std::string_view jsonText(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (binary)
        if (Status s = checkGlb(bytes, jsonText); !s) return Error{s.error()};
    if (Status s = patchForTinygltf(bytes, binary, jsonText); !s) return Error{s.error()};
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
    Scene scene;
    scene.source = name;
    imageProblems.resize(model.images.size());
    for (size_t i = 0; i < model.images.size(); ++i)
        if (imageProblems[i].empty() && model.images[i].image.empty())
            imageProblems[i] = "could not be read (" + firstLine(tinyWarn) + ")";

    bool anyMeshopt = false;
    if (Status s = decodeMeshopt(model, anyMeshopt); !s) return Error{s.error()};
    if (anyMeshopt) scene.extensions.push_back("EXT_meshopt_compression (meshoptimizer)");
    std::vector<uint8_t> dracoAccessor(model.accessors.size(), 0);
    bool anyDraco = false;
    for (const tinygltf::Mesh& mesh : model.meshes)
        for (const tinygltf::Primitive& p : mesh.primitives) {
            if (!hasDraco(p)) continue;
            anyDraco = true;
            for (const auto& [name, index] : p.attributes)
                if (index >= 0 && size_t(index) < dracoAccessor.size())
                    dracoAccessor[size_t(index)] = 1;
            if (p.indices >= 0 && size_t(p.indices) < dracoAccessor.size())
                dracoAccessor[size_t(p.indices)] = 1;
        }
    if (anyDraco) scene.extensions.push_back("KHR_draco_mesh_compression (libdraco)");
    for (size_t i = 0; i < model.accessors.size(); ++i)
        if (Status s = checkAccessor(model, i, dracoAccessor[i] != 0); !s) return Error{s.error()};
    std::vector<Instance> instances;
    if (Status s = collectInstances(model, instances); !s) return Error{s.error()};
    if (Status s = checkDeclaredSize(model, instances); !s) return Error{s.error()};
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
    const int camera = placeCamera(model, instances, scene);
    if (options.cameraIndex) *options.cameraIndex = camera;
    return scene;
}

bool hasGlbExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext)
        c = char(std::tolower(uint8_t(c)));
    return ext == ".glb";
}

// Every failure, including running out of memory, becomes one printable line naming `name`.
Result<Scene> guarded(const std::string& name, const GltfLoadOptions& options,
                      const std::function<Result<Scene>(const WarnFn&)>& body) {
    auto warn = [&](const std::string& line) {
        if (options.warnings) options.warnings->push_back(printableLine(name + ": " + line));
    };
    std::string problem;
    try {
        Result<Scene> scene = body(warn);
        if (scene.ok()) return scene;
        problem = scene.error();
    } catch (const std::bad_alloc&) {
        problem = "out of memory while loading";
    } catch (const std::exception& e) {
        problem = "unexpected failure: " + firstLine(e.what());
    }
    return Error{printableLine(name + ": " + problem)};
}

} // namespace

namespace gltf {

Result<Scene> loadGltfBytes(std::vector<unsigned char> bytes, const std::string& name,
                            const fs::path& folder, bool binary, const GltfLoadOptions& options) {
    return guarded(name, options, [&](const WarnFn& warn) {
        return parse(bytes, name, fs::absolute(folder).lexically_normal(), binary, options, warn);
    });
}

} // namespace gltf

Result<Scene> loadGltf(const std::string& path, const GltfLoadOptions& options) {
    return guarded(path, options, [&](const WarnFn& warn) -> Result<Scene> {
        std::vector<unsigned char> bytes;
        if (Status s = readFile(path, bytes); !s) return Error{s.error()};
        const fs::path folder = fs::absolute(fs::path(path)).parent_path().lexically_normal();
        return parse(bytes, path, folder, hasGlbExtension(path), options, warn);
    });
}

} // namespace tp
