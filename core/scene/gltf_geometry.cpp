// glTF primitives: strip/fan conversion, attributes read and repaired, transformation into
// world space (generated normals and tangents: gltf_normals.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/scene/gltf_internal.h"

namespace tp::gltf {
namespace {

// Strips and fans to lists (glTF 2.0 spec, 3.7.2.1); a list keeps whole triangles only.
std::vector<uint32_t> toTriangleList(const std::vector<uint32_t>& in, int mode) {
    std::vector<uint32_t> out;
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (size_t i = 0; i + 2 < in.size(); ++i) {
            if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
                out.insert(out.end(), {in[i + 1], in[i + 2], in[0]});
            else if (i % 2 == 0)
                out.insert(out.end(), {in[i], in[i + 1], in[i + 2]});
            else
                out.insert(out.end(), {in[i], in[i + 2], in[i + 1]});
        }
        return out;
    }
    out = in;
    out.resize(in.size() / 3 * 3);
    return out;
}

} // namespace

namespace {

const AttributeSpec kPosition{
    "POSITION", {TINYGLTF_TYPE_VEC3}, {kFloat, kByte, kUByte, kShort, kUShort}, false};
const AttributeSpec kNormal{"NORMAL", {TINYGLTF_TYPE_VEC3}, {kFloat, kByte, kShort}, true};
const AttributeSpec kTangent{"TANGENT", {TINYGLTF_TYPE_VEC4}, {kFloat, kByte, kShort}, true};
// Non-normalized integer uvs are KHR_mesh_quantization's; they are read as they are.
const AttributeSpec kUv{
    "TEXCOORD_0", {TINYGLTF_TYPE_VEC2}, {kFloat, kByte, kUByte, kShort, kUShort}, false};
const AttributeSpec kColor{
    "COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, {kFloat, kUByte, kUShort}, true};

// One primitive's attributes: from the Draco bitstream when the extension lists them, else
// from their accessors. `data` and `comps` hold the attribute fetched last.
struct AttributeReader {
    const tinygltf::Model& model;
    const tinygltf::Primitive& p;
    DracoPrimitive draco;
    std::vector<float> data;
    size_t comps = 0;

    int accessor(const char* name) const {
        auto it = p.attributes.find(name);
        return it == p.attributes.end() ? -1 : it->second;
    }

    Status fetch(const AttributeSpec& spec, int index, bool keepNonFinite) {
        auto it = draco.attributes.find(spec.name);
        if (it == draco.attributes.end())
            return readFloats(model, index, spec, data, comps, keepNonFinite);
        data = std::move(it->second);
        comps = draco.comps[spec.name];
        if (!keepNonFinite)
            for (float v : data)
                if (!std::isfinite(v))
                    return Error{std::string(spec.name) + " accessor " + std::to_string(index) +
                                 " (Draco) holds a NaN or infinite value"};
        return {};
    }
};

// Vertices whose value must be replaced, per attribute (empty: none).
struct BadVertices {
    std::vector<uint8_t> normal, tangent;
};

bool finite(const float* v, size_t k) {
    for (size_t c = 0; c < k; ++c)
        if (!std::isfinite(v[c])) return false;
    return true;
}

// A vector attribute's element that cannot give a direction: marked in `bad` for a repair.
bool markIfNoDirection(const float* v, size_t k, glm::vec3 d, size_t i, size_t n,
                       std::vector<uint8_t>& bad) {
    float len2 = glm::dot(d, d);
    if (finite(v, k) && len2 > 1e-30f && std::isfinite(len2)) return false;
    if (bad.empty()) bad.assign(n, 0);
    bad[i] = 1;
    return true;
}

// Each store* fills its attribute from `data` and returns how many values it replaced.
size_t storeNormals(const std::vector<float>& data, size_t n, LocalPrimitive& out,
                    std::vector<uint8_t>& bad) {
    out.normals.resize(n);
    size_t count = 0;
    for (size_t i = 0; i < n; ++i) {
        glm::vec3 v(data[3 * i], data[3 * i + 1], data[3 * i + 2]);
        count += markIfNoDirection(&data[3 * i], 3, v, i, n, bad);
        out.normals[i] = safeNormalize(v, glm::vec3(0, 1, 0));
    }
    return count;
}

size_t storeTangents(const std::vector<float>& data, size_t n, LocalPrimitive& out,
                     std::vector<uint8_t>& bad) {
    out.tangents.resize(n);
    size_t count = 0;
    for (size_t i = 0; i < n; ++i) {
        glm::vec3 t(data[4 * i], data[4 * i + 1], data[4 * i + 2]);
        count += markIfNoDirection(&data[4 * i], 4, t, i, n, bad);
        out.tangents[i] = glm::vec4(t, data[4 * i + 3] < 0.0f ? -1.0f : 1.0f);
    }
    return count;
}

size_t storeUvs(const std::vector<float>& data, size_t n, LocalPrimitive& out) {
    out.uvs.resize(n);
    size_t count = 0;
    for (size_t i = 0; i < n; ++i) {
        out.uvs[i] = glm::vec2(data[2 * i], data[2 * i + 1]);
        if (!finite(&data[2 * i], 2)) {
            out.uvs[i] = glm::vec2(0.0f);
            ++count;
        }
    }
    return count;
}

size_t storeColors(const std::vector<float>& data, size_t comps, size_t n, LocalPrimitive& out) {
    out.colors.resize(n);
    size_t count = 0;
    for (size_t i = 0; i < n; ++i) {
        out.colors[i] = glm::vec4(data[comps * i], data[comps * i + 1], data[comps * i + 2],
                                  comps == 4 ? data[comps * i + 3] : 1.0f);
        if (!finite(&data[comps * i], comps)) {
            out.colors[i] = glm::vec4(1.0f);
            ++count;
        }
    }
    return count;
}

std::string shortNumber(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(v));
    return text;
}

// Finite uvs past kMaxUvMagnitude (the repair of non-finite ones has run): clamped and
// recorded, or, under --strict, an error naming the accessor and the value.
Status clampHugeUvs(int accessor, bool strict, LocalPrimitive& out) {
    size_t count = 0;
    float largest = 0.0f;
    for (const glm::vec2& uv : out.uvs)
        if (float m = std::max(std::abs(uv.x), std::abs(uv.y)); m > kMaxUvMagnitude) {
            ++count;
            largest = std::max(largest, m);
        }
    if (count == 0) return {};
    const std::string limit = shortNumber(kMaxUvMagnitude);
    if (strict)
        return Error{"TEXCOORD_0 accessor " + std::to_string(accessor) + " holds a uv of " +
                     shortNumber(largest) + ", past the " + limit +
                     " at which texture addressing overflows on the GPU"};
    for (glm::vec2& uv : out.uvs)
        uv = glm::clamp(uv, -kMaxUvMagnitude, kMaxUvMagnitude);
    out.repairs.push_back(SceneRepair{"TEXCOORD_0", accessor, count, out.uvs.size(),
                                      "finite but past " + limit + " (largest " +
                                          shortNumber(largest) +
                                          "), where texture addressing overflows on the GPU",
                                      "clamped to +-" + limit});
    return {};
}

// POSITION, then the optional attributes; values that are not finite are refused under
// --strict and otherwise repaired (each repair recorded in out.repairs).
Status readVertexAttributes(AttributeReader& r, const PrimitiveOptions& options,
                            LocalPrimitive& out, BadVertices& bad) {
    Status s = r.fetch(kPosition, r.accessor("POSITION"), false);
    if (!s) return s;
    const std::vector<float>& data = r.data;
    const size_t n = data.size() / 3;
    out.positions.resize(n);
    for (size_t i = 0; i < n; ++i) // a loop, not memcpy: data.data() is null when n == 0
        out.positions[i] = glm::vec3(data[3 * i], data[3 * i + 1], data[3 * i + 2]);
    const bool keep = !options.strict; // non-finite values are repaired later, not refused
    auto readOptional = [&](const AttributeSpec& spec, const char* problem, const char* action,
                            auto&& store) -> Status {
        int index = r.accessor(spec.name);
        if (index < 0) return {};
        // Compared before reading: an attribute's count is not bounded by POSITION's.
        if (size_t(index) < r.model.accessors.size() && r.model.accessors[size_t(index)].count != n)
            return Error{std::string(spec.name) + " has " +
                         std::to_string(r.model.accessors[size_t(index)].count) +
                         " elements but POSITION has " + std::to_string(n)};
        Status f = r.fetch(spec, index, keep);
        if (!f) return f;
        if (size_t count = store(); count > 0)
            out.repairs.push_back(SceneRepair{spec.name, index, count, n, problem, action});
        return {};
    };
    s = readOptional(
        kNormal, "NaN, infinite or zero-length",
        "replaced by the area-weighted average of the face normals of the triangles using "
        "the vertex",
        [&] { return storeNormals(data, n, out, bad.normal); });
    if (s)
        s = readOptional(kTangent, "NaN, infinite or zero-length",
                         "regenerated from the positions, normals and uvs",
                         [&] { return storeTangents(data, n, out, bad.tangent); });
    if (s)
        s = readOptional(kUv, "NaN or infinite", "set to (0, 0)",
                         [&] { return storeUvs(data, n, out); });
    if (s) s = clampHugeUvs(r.accessor(kUv.name), options.strict, out);
    if (s)
        s = readOptional(kColor, "NaN or infinite", "set to white, opaque",
                         [&] { return storeColors(data, r.comps, n, out); });
    return s;
}

// The primitive's indices (the bitstream's, the accessor's or 0..n-1), each below n.
Status readIndexList(AttributeReader& r, bool compressed, size_t n,
                     std::vector<uint32_t>& indices) {
    if (compressed) {
        indices = std::move(r.draco.indices);
        for (uint32_t i : indices)
            if (i >= n)
                return Error{"Draco index " + std::to_string(i) + " is out of range (" +
                             std::to_string(n) + " vertices)"};
    } else if (r.p.indices >= 0) {
        return readIndices(r.model, r.p.indices, n, indices);
    } else {
        indices.resize(n);
        for (uint32_t i = 0; i < n; ++i)
            indices[i] = i;
    }
    return {};
}

// Returns how many uvs the transform took past kMaxUvMagnitude (clamped, as the accessor's are).
size_t applyUvTransform(const tinygltf::Material& material, std::vector<glm::vec2>& uvs) {
    const UvTransform t = materialUvTransform(material);
    if (!t.present) return 0;
    size_t clamped = 0;
    for (glm::vec2& uv : uvs) {
        uv = t.matrix * glm::vec3(uv, 1.0f);
        // Huge (finite) uvs times a scale can overflow: an infinity is clamped below as a huge
        // uv is; a NaN (infinities cancelling in the rotation) means no texel, (0, 0).
        if (std::isnan(uv.x) || std::isnan(uv.y)) uv = glm::vec2(0.0f);
        const glm::vec2 kept = glm::clamp(uv, -kMaxUvMagnitude, kMaxUvMagnitude);
        clamped += kept != uv;
        uv = kept;
    }
    return clamped;
}

// Repairs the bad normals from the faces, or makes all of them where the file has none.
void completeNormals(bool smoothNormals, BadVertices& bad, LocalPrimitive& out) {
    if (!bad.normal.empty()) {
        std::vector<glm::vec3> smooth;
        makeSmoothNormals(out.positions, out.indices, smooth);
        for (size_t i = 0; i < out.normals.size(); ++i)
            if (bad.normal[i]) out.normals[i] = smooth[i];
    }
    if (!out.normals.empty()) return;
    // The spec asks for flat normals; smooth ones are an option.
    if (smoothNormals) {
        makeSmoothNormals(out.positions, out.indices, out.normals);
    } else {
        if (!bad.tangent.empty()) deindex(bad.tangent, out.indices);
        makeFlatNormals(out);
    }
}

// From the uvs where a normal map will read them, else any vector perpendicular to the normal.
void generateTangents(bool normalMapped, const LocalPrimitive& p,
                      std::vector<glm::vec4>& tangents) {
    if (normalMapped) {
        makeTangents(p.positions, p.normals, p.uvs, p.indices, tangents);
        return;
    }
    tangents.resize(p.positions.size());
    for (size_t i = 0; i < p.positions.size(); ++i)
        tangents[i] = glm::vec4(anyPerpendicular(p.normals[i]), 1.0f);
}

// Repairs the bad tangents, or makes all of them where the file has none.
void completeTangents(bool normalMapped, const std::vector<uint8_t>& badTangent,
                      LocalPrimitive& out) {
    if (out.tangents.empty()) {
        generateTangents(normalMapped, out, out.tangents);
    } else if (!badTangent.empty()) {
        std::vector<glm::vec4> generated;
        generateTangents(normalMapped, out, generated);
        for (size_t i = 0; i < out.tangents.size(); ++i)
            if (badTangent[i]) out.tangents[i] = generated[i];
    }
}

} // namespace

Status readPrimitive(const tinygltf::Model& model, int meshIndex, int primIndex,
                     const PrimitiveOptions& options, LocalPrimitive& out, const WarnFn& warn) {
    const tinygltf::Mesh& mesh = model.meshes[size_t(meshIndex)];
    const tinygltf::Primitive& p = mesh.primitives[size_t(primIndex)];
    std::string label =
        "mesh " + std::to_string(meshIndex) + " primitive " + std::to_string(primIndex);
    auto fail = [&](const Status& s) { return Error{label + ": " + s.error()}; };
    out = LocalPrimitive{};
    out.material = p.material;
    int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        warn(label + ": mode " + std::to_string(mode) + " (points or lines) skipped");
        return {};
    }
    AttributeReader reader{model, p};
    if (reader.accessor("POSITION") < 0) {
        warn(label + ": no POSITION attribute, skipped");
        return {};
    }
    const bool compressed = hasDraco(p);
    if (compressed) {
        Status d = decodeDraco(model, p, {kPosition, kNormal, kTangent, kUv, kColor}, reader.draco);
        if (!d) return fail(d);
        mode = TINYGLTF_MODE_TRIANGLES; // the bitstream's faces, whatever the mode (strips) said
    }
    BadVertices bad;
    Status s = readVertexAttributes(reader, options, out, bad);
    if (!s) return fail(s);
    const size_t n = out.positions.size();
    std::vector<uint32_t> indices;
    s = readIndexList(reader, compressed, n, indices);
    if (!s) return fail(s);
    if (mode == TINYGLTF_MODE_TRIANGLES && indices.size() % 3 != 0)
        warn(label + ": " + std::to_string(indices.size()) +
             " indices is not a multiple of 3; the last partial triangle is dropped");
    out.indices = toTriangleList(indices, mode);
    if (out.indices.empty()) {
        warn(label + ": no triangles, skipped");
        out.positions.clear();
        return {};
    }

    if (out.uvs.empty()) out.uvs.assign(n, glm::vec2(0.0f));
    if (out.colors.empty()) out.colors.assign(n, glm::vec4(1.0f));
    const tinygltf::Material* material =
        p.material >= 0 && size_t(p.material) < model.materials.size()
            ? &model.materials[size_t(p.material)]
            : nullptr;
    if (size_t c = material ? applyUvTransform(*material, out.uvs) : 0; c > 0)
        warn(label + ": material " + std::to_string(p.material) +
             "'s KHR_texture_transform takes " + std::to_string(c) + " uvs past " +
             shortNumber(kMaxUvMagnitude) + "; clamped there");
    completeNormals(options.smoothNormals, bad, out);
    completeTangents(material && material->normalTexture.index >= 0, bad.tangent, out);
    return {};
}

void appendTransformed(const LocalPrimitive& prim, const glm::mat4& world, Mesh& out) {
    const glm::mat3 m(world);
    const float det = glm::determinant(m);
    // The cofactor matrix is det * inverse-transpose: defined even for det == 0, and with the
    // sign of det removed it gives the inverse-transpose's directions.
    glm::mat3 cof(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1]));
    const glm::mat3 normalMatrix = det < 0.0f ? -cof : cof;
    const float mirror = det < 0.0f ? -1.0f : 1.0f;
    const uint32_t base = uint32_t(out.positions.size());
    for (size_t i = 0; i < prim.positions.size(); ++i) {
        out.positions.push_back(glm::vec3(world * glm::vec4(prim.positions[i], 1.0f)));
        glm::vec3 n = safeNormalize(normalMatrix * prim.normals[i], glm::vec3(0, 1, 0));
        out.normals.push_back(n);
        glm::vec3 t = safeNormalize(m * glm::vec3(prim.tangents[i]), anyPerpendicular(n));
        out.tangents.push_back(glm::vec4(t, prim.tangents[i].w * mirror));
    }
    out.uvs.insert(out.uvs.end(), prim.uvs.begin(), prim.uvs.end());
    out.colors.insert(out.colors.end(), prim.colors.begin(), prim.colors.end());
    for (size_t t = 0; t + 2 < prim.indices.size(); t += 3) {
        uint32_t a = prim.indices[t], b = prim.indices[t + 1], c = prim.indices[t + 2];
        if (det < 0.0f) std::swap(b, c);
        out.indices.insert(out.indices.end(), {base + a, base + b, base + c});
    }
}

} // namespace tp::gltf
