#pragma once
// Internal to the glTF loader (gltf_*.cpp) and its tests; not a public interface.
// Every function that reads the tinygltf::Model checks indices and byte ranges itself: the
// model comes from an untrusted file and tinygltf 2.7 validates little. Error and warning
// texts here do not name the file; loadGltf() prefixes "PATH: ".
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "core/scene/gltf_loader.h"
#include "core/scene/scene.h"
#include "core/util/result.h"

namespace tp::gltf {

// Limits that keep a hostile file from asking for gigabytes (docs/hostile_input.md). Data
// read from a bufferView is bounded by the file's size; these bound what is not.
// Vertices, and indices, in the whole scene once every node's meshes are placed: 2^24
// vertices are 1 GiB of vertex attributes (64 bytes each), far past any scene this tool
// renders in reasonable time, and instancing can multiply a small file's mesh without limit.
constexpr int kMaxElementsLog2 = 24;
constexpr uint64_t kMaxElements = 1ull << kMaxElementsLog2;
// An accessor without a bufferView is zeros (plus its sparse values): no byte of the file
// bounds its count. 2^20 elements are 64 MiB even as VEC4 floats.
constexpr int kMaxZeroFilledLog2 = 20;
constexpr uint64_t kMaxZeroFilled = 1ull << kMaxZeroFilledLog2;
constexpr int kMaxTextureSide = 16384;
// Pixels of every texture a material uses, read from the image headers before any decoding:
// 2^28 pixels are 1 GiB as RGBA8 (Sponza's textures are ~2^26).
constexpr int kMaxTexturePixelsLog2 = 28;
constexpr uint64_t kMaxTexturePixels = 1ull << kMaxTexturePixelsLog2;
// The largest uv magnitude kept; larger ones are clamped to it (a repair: --strict refuses).
// The sampler scales a uv by the texture's side (up to kMaxTextureSide = 2^14), and the
// difference of two neighbouring pixels' uvs by it for the mip level: past about 2e34 the
// first overflows fp32 and the texel address is undefined. 2^112 keeps the second, at most
// 2^113 x 2^14 = 2^127, below FLT_MAX too. Nothing visible is lost: past 2^24 an fp32 uv holds
// no fraction, and a triangle spanning 2^112 repeats shows the coarsest mip either way.
constexpr float kMaxUvMagnitude = 0x1p112f;

using WarnFn = std::function<void(const std::string&)>;

// The first non-blank line of a (tinygltf or library) message, trimmed.
std::string firstLine(const std::string& text);

constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE;
constexpr int kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int kShort = TINYGLTF_COMPONENT_TYPE_SHORT;
constexpr int kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr int kUInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;

// Loads a glTF from bytes already in memory, as loadGltf does with a file's: `name` prefixes
// every message, external files resolve in `folder`, `binary` when the name ends in .glb
// (the GLB magic is recognised whatever it is). For the fuzz target and the tests.
Result<Scene> loadGltfBytes(std::vector<unsigned char> bytes, const std::string& name,
                            const std::filesystem::path& folder, bool binary,
                            const GltfLoadOptions& options = {});

// --- gltf_files.cpp ----------------------------------------------------------------------

// The files tinygltf may open (lexically normal absolute path -> bytes to read, 0 = all).
struct FileAccess {
    std::map<std::string, uint64_t> allowed;
};

// Reads a whole file: missing, empty and over-4-GiB files are errors.
Status readFile(const std::string& path, std::vector<unsigned char>& bytes);
// The GLB container (glTF 2.0 spec, 4.4); `jsonText` receives the JSON chunk.
Status checkGlb(const std::vector<unsigned char>& bytes, std::string_view& jsonText);
// Parses the JSON; checks asset.version and extensionsRequired (warns about extensions used
// but ignored); checks every buffer URI (an error if absolute, with a scheme, leaving
// `folder`, missing or shorter than byteLength) and every image URI (a problem recorded in
// imageProblems[i], later a placeholder); fills `access` with the files that passed.
Status prescan(std::string_view jsonText, const std::filesystem::path& folder, bool binary,
               FileAccess& access, std::vector<std::string>& imageProblems, const WarnFn& warn);
// Rewrites what tinygltf 2.7 refuses in compressed files, before it parses (`bytes` and
// `jsonText` replaced; for a GLB, its JSON chunk; a no-op for other files):
// - an EXT_meshopt_compression fallback buffer without a uri (its bytes exist only compressed)
//   gets a one-byte data URI;
// - a KHR_draco_mesh_compression primitive's index accessor without a bufferView (its indices
//   are in the bitstream) names the Draco bufferView, which tinygltf demands of any index
//   accessor; checkAccessor(compressed) never reads through it.
Status patchForTinygltf(std::vector<unsigned char>& bytes, bool binary, std::string_view& jsonText);

// Small readers shared by gltf_files.cpp and gltf_patch.cpp: a little-endian word of a GLB,
// an object's member (null when absent or not an object), an array member (empty when absent).
uint32_t readLe32(const unsigned char* p);
const nlohmann::json* jsonMember(const nlohmann::json& object, const char* key);
const nlohmann::json& jsonArray(const nlohmann::json& root, const char* key);
// Routes tinygltf's file access through `access` (which must outlive the load) and makes it
// keep images encoded (tinygltf::Image::as_is) for loadMaterials to decode.
void confine(tinygltf::TinyGLTF& loader, FileAccess& access);

// --- gltf_nodes.cpp ----------------------------------------------------------------------

struct Instance {
    int node; // -1: a mesh drawn without a node (file without nodes)
    int mesh;
    glm::mat4 world;
};

// The nodes of the default scene (scene 0 if none is named), depth first, with their world
// matrices. A file without scenes shows its root nodes; one without nodes, each mesh once.
Status collectInstances(const tinygltf::Model& model, std::vector<Instance>& out);
// Adds the node's KHR_lights_punctual light, if any, placed by its world matrix.
void addLight(const tinygltf::Model& model, const Instance& inst, Scene& scene, const WarnFn& warn);
// The file's first perspective camera on a drawn node, else one framing scene.bounds.
// Returns that camera's index into the file's "cameras", or -1 when it framed the bounds.
int placeCamera(const tinygltf::Model& model, const std::vector<Instance>& instances, Scene& scene);

// --- gltf_accessors.cpp ------------------------------------------------------------------

// Checks one accessor (and its sparse part) against the bufferViews and the buffer bytes
// tinygltf actually loaded. loadGltf runs it on every accessor, used or not. `compressed`: a
// Draco primitive's accessor, whose data comes from the bitstream: only its type and count
// are checked (the 2^24 limit; not the 2^20 one of zero-filled accessors, which it is not).
Status checkAccessor(const tinygltf::Model& model, size_t index, bool compressed = false);

// What an attribute may hold.
struct AttributeSpec {
    const char* name;
    std::vector<int> types;          // TINYGLTF_TYPE_*
    std::vector<int> componentTypes; // allowed componentType values
    bool forceNormalized;            // integer data is always normalized (COLOR_0)
};

// Reads a float attribute (integers converted, normalized ones to [0,1] or [-1,1]; sparse
// values applied); `comps` receives the element width (3 or 4 for COLOR_0). Errors name the
// attribute and accessor; NaN and infinity are errors unless `keepNonFinite` (the caller
// repairs them).
Status readFloats(const tinygltf::Model& model, int index, const AttributeSpec& spec,
                  std::vector<float>& out, size_t& comps, bool keepNonFinite = false);
// Reads an index accessor; every index must be below vertexCount.
Status readIndices(const tinygltf::Model& model, int index, size_t vertexCount,
                   std::vector<uint32_t>& out);

// --- gltf_draco.cpp ---------------------------------------------------------------------

// A KHR_draco_mesh_compression primitive, decoded: float attributes by glTF name (integers
// converted as readFloats does), triangle-list indices.
struct DracoPrimitive {
    size_t points = 0;
    std::map<std::string, std::vector<float>> attributes;
    std::map<std::string, size_t> comps;
    std::vector<uint32_t> indices;
};

bool hasDraco(const tinygltf::Primitive& p);
// Decodes the primitive's bitstream: the attributes of `specs` the extension lists. The
// decoded vertex and index counts must equal those of the POSITION and index accessors.
Status decodeDraco(const tinygltf::Model& model, const tinygltf::Primitive& p,
                   const std::vector<AttributeSpec>& specs, DracoPrimitive& out);

// --- gltf_meshopt.cpp --------------------------------------------------------------------

// Decodes every EXT_meshopt_compression bufferView into a buffer of its own and points the
// view at it (before checkAccessor). Truncated or corrupt data, and a view declaring more
// than its compressed bytes can hold, are errors. `any`: some view was decoded.
Status decodeMeshopt(tinygltf::Model& model, bool& any);

// --- gltf_geometry.cpp -------------------------------------------------------------------

// One primitive as read from the file, in its mesh's local space, as a triangle list; every
// attribute array has positions.size() entries once readPrimitive returns.
struct LocalPrimitive {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec4> tangents;
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec4> colors;
    std::vector<uint32_t> indices;
    int material = -1;                // as in the file, unchecked
    std::vector<SceneRepair> repairs; // readPrimitive's replacements, per attribute and problem
};

struct PrimitiveOptions {
    bool smoothNormals = false; // missing normals: area-weighted smooth instead of flat
    bool strict = false;        // non-finite attribute values and huge uvs are errors, not repairs
};

// Reads primitive `prim` of mesh `mesh` (indices already checked by the caller), converting
// strips and fans and generating what is missing. Zero-length normals and tangents and,
// unless options.strict (then an error), NaN/infinite normals, tangents, uvs and colours and
// uvs beyond kMaxUvMagnitude are replaced and listed in out.repairs (the caller warns). Returns an
// error for invalid data; sets `out.positions` empty (with a warning) for a primitive that is
// skipped (points, lines, no POSITION).
Status readPrimitive(const tinygltf::Model& model, int mesh, int prim,
                     const PrimitiveOptions& options, LocalPrimitive& out, const WarnFn& warn);

// Appends `prim` transformed by `world` to `out`: normals by the inverse-transpose, tangents
// by the matrix with w flipped when the determinant is negative, and the winding flipped then
// too so that front faces stay front faces.
void appendTransformed(const LocalPrimitive& prim, const glm::mat4& world, Mesh& out);

// v[indices[i]] for each i: a vertex per index (flat normals, repairs per face corner).
template <class T> void deindex(std::vector<T>& v, const std::vector<uint32_t>& indices) {
    if (v.empty()) return;
    std::vector<T> out(indices.size());
    for (size_t i = 0; i < indices.size(); ++i)
        out[i] = v[indices[i]];
    v.swap(out);
}

// Flat normals need one vertex per triangle corner: de-indexes every attribute, then sets each
// corner's normal to its face normal.
void makeFlatNormals(LocalPrimitive& prim);
// Area-weighted average of the face normals around each vertex (vertices are not welded).
void makeSmoothNormals(const std::vector<glm::vec3>& positions,
                       const std::vector<uint32_t>& indices, std::vector<glm::vec3>& normals);
// Per-vertex tangents from the uvs (Lengyel), Gram-Schmidt against the normals, handedness in
// w with the glTF convention: bitangent = cross(normal, tangent.xyz) * w points toward
// decreasing v ("up" in the image). Vertices whose uvs are degenerate get any unit tangent
// perpendicular to the normal, w = +1.
void makeTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                  const std::vector<glm::vec2>& uvs, const std::vector<uint32_t>& indices,
                  std::vector<glm::vec4>& tangents);
glm::vec3 anyPerpendicular(const glm::vec3& n);
// v / |v|, or `fallback` where v has no direction (zero, tiny, not finite).
glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback);

// --- gltf_materials.cpp ------------------------------------------------------------------

// Converts a decoded tinygltf image (1-4 channels, 8 or 16 bits) to RGBA8: grey to grey,
// missing alpha to 255, 16-bit rounded to 8. False when the size or layout is inconsistent.
bool toRgba8(const unsigned char* data, size_t size, int width, int height, int components,
             int bits, std::vector<uint8_t>& rgba8);

// KHR_texture_transform of a material, baked into the vertex uvs by readPrimitive. A vertex
// has one uv set, so this is faithful only when every texture of the material has the same
// transform (a texture without the extension has the identity); otherwise `problem` says which
// slot's `matrix` is applied to all (the first textured one: base colour, metal-rough, normal,
// occlusion, emissive) and loadMaterials warns once per material.
constexpr const char* kTextureTransform = "KHR_texture_transform";
struct UvTransform {
    bool present = false;     // some texture of the material has the extension
    glm::mat3x2 matrix{1.0f}; // uv' = matrix * vec3(uv, 1)
    std::string problem;      // non-empty: what is not applied faithfully (one line)
};
UvTransform materialUvTransform(const tinygltf::Material& m);

// Fills scene.materials (one per glTF material, in order) and scene.textures (one per
// (image, sRGB) pair actually used, images decoded in parallel). Images the file could not
// provide (imageProblems[i] non-empty), PNGs checkPng refuses and images that fail to decode
// become 1x1 placeholders with one warning each. A texture over kMaxTextureSide is an error.
Status loadMaterials(const tinygltf::Model& model, const std::vector<std::string>& imageProblems,
                     Scene& scene, const WarnFn& warn);

// --- gltf_image_checks.cpp ----------------------------------------------------------------

// What stb_image would trust in a PNG (peekImageSize has accepted its header), checked before
// it decodes: every chunk inside the image's bytes, and the IDAT stream inflating (zlib, through
// a small window) to at most twice the scanlines IHDR's size needs, so that stb's buffers stay
// bounded by the image's size. "" when it may be decoded, else why not (one line). `cleaned`
// receives a copy without the zero-length IDAT chunks when there are some (stb copies a leading
// one into a null pointer), else is left empty.
std::string checkPng(const unsigned char* bytes, size_t size, std::vector<unsigned char>& cleaned);
// Reads the width and height from a PNG or JPEG header without decoding it.
bool peekImageSize(const unsigned char* bytes, size_t size, int& width, int& height);

} // namespace tp::gltf
