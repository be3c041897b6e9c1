// The scenes of gltf_test_scenes.h. Each is one .gltf with one .bin beside it; the JSON is
// written by nlohmann::json, the compressed streams by libdraco's and meshoptimizer's encoders.
#include "gltf_test_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include "core/image/image_io.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kFloat = 5126, kUInt = 5125, kByte = 5120;

// A .gltf under construction: one buffer, views appended 4-aligned.
struct Writer {
    json gltf;
    std::vector<uint8_t> bin;

    Writer() {
        gltf = json::parse(R"({
          "asset": {"version": "2.0", "generator": "triptych tests"},
          "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
          "meshes": [{"primitives": [{"attributes": {}, "material": 0}]}],
          "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                                  "metallicFactor": 0, "roughnessFactor": 0.6}}],
          "textures": [{"source": 0}], "images": [{"uri": "checker.png"}],
          "accessors": [], "bufferViews": [], "buffers": []})");
    }
    int view(const void* data, size_t size, int buffer = 0) {
        while (bin.size() % 4)
            bin.push_back(0);
        const size_t offset = bin.size();
        bin.insert(bin.end(), (const uint8_t*)data, (const uint8_t*)data + size);
        gltf["bufferViews"].push_back(
            {{"buffer", buffer}, {"byteOffset", offset}, {"byteLength", size}});
        return int(gltf["bufferViews"].size()) - 1;
    }
    int accessor(json a) {
        gltf["accessors"].push_back(std::move(a));
        return int(gltf["accessors"].size()) - 1;
    }
    json& primitive() { return gltf["meshes"][0]["primitives"][0]; }
    fs::path write(const fs::path& dir) {
        fs::create_directories(dir);
        gltf["buffers"].insert(gltf["buffers"].begin(),
                               json{{"uri", "scene.bin"}, {"byteLength", bin.size()}});
        std::ofstream(dir / "scene.bin", std::ios::binary)
            .write((const char*)bin.data(), std::streamsize(bin.size()));
        // An 8 x 8 checker, red and white: where the texture transform shows.
        ImageRGBA checker(8, 8);
        for (uint32_t y = 0; y < 8; ++y)
            for (uint32_t x = 0; x < 8; ++x) {
                const bool red = (x + y) % 2 == 0;
                float* p = &checker.rgba[(y * 8 + x) * 4];
                p[0] = 1.0f;
                p[1] = p[2] = red ? 0.1f : 1.0f;
                p[3] = 1.0f;
            }
        if (Status s = writePng((dir / "checker.png").string(), checker); !s)
            throw std::runtime_error(s.error());
        const fs::path path = dir / "scene.gltf";
        std::ofstream(path) << gltf.dump(1);
        return path;
    }
};

json minMax(const std::vector<glm::vec3>& p) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& v : p) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    return {{"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}};
}

// Plain accessors for the mesh; returns the primitive's attributes and indices.
void addPlain(Writer& w, const TestMesh& m) {
    json pos = {{"bufferView", w.view(m.positions.data(), m.positions.size() * 12)},
                {"componentType", kFloat},
                {"count", m.positions.size()},
                {"type", "VEC3"}};
    pos.update(minMax(m.positions));
    json& prim = w.primitive();
    prim["attributes"]["POSITION"] = w.accessor(pos);
    prim["attributes"]["NORMAL"] =
        w.accessor({{"bufferView", w.view(m.normals.data(), m.normals.size() * 12)},
                    {"componentType", kFloat},
                    {"count", m.normals.size()},
                    {"type", "VEC3"}});
    prim["attributes"]["TEXCOORD_0"] =
        w.accessor({{"bufferView", w.view(m.uvs.data(), m.uvs.size() * 8)},
                    {"componentType", kFloat},
                    {"count", m.uvs.size()},
                    {"type", "VEC2"}});
    prim["indices"] = w.accessor({{"bufferView", w.view(m.indices.data(), m.indices.size() * 4)},
                                  {"componentType", kUInt},
                                  {"count", m.indices.size()},
                                  {"type", "SCALAR"}});
}

} // namespace

TestMesh makeTestMesh() {
    TestMesh m;
    const int rings = 16, segments = 24;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            const float theta = float(M_PI) * float(r) / rings,
                        phi = 2.0f * float(M_PI) * float(s) / segments;
            glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                        std::sin(theta) * std::sin(phi));
            m.positions.push_back(n + glm::vec3(0, 1, 0));
            m.normals.push_back(n);
            m.uvs.push_back(glm::vec2(float(s) / segments, float(r) / rings));
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const uint32_t a = uint32_t(r * (segments + 1) + s), b = a + uint32_t(segments + 1);
            m.indices.insert(m.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
        }
    const uint32_t base = uint32_t(m.positions.size());
    for (int i = 0; i < 4; ++i) {
        const float x = (i & 1) ? 3.0f : -3.0f, z = (i & 2) ? 3.0f : -3.0f;
        m.positions.push_back(glm::vec3(x, 0, z));
        m.normals.push_back(glm::vec3(0, 1, 0));
        m.uvs.push_back(glm::vec2((x + 3) / 6 * 3, (z + 3) / 6 * 3));
    }
    m.indices.insert(m.indices.end(), {base, base + 2, base + 1, base + 1, base + 2, base + 3});
    return m;
}

fs::path writePlainScene(const fs::path& dir) {
    Writer w;
    addPlain(w, makeTestMesh());
    return w.write(dir);
}

fs::path writeRepairScene(const fs::path& dir, RepairCounts& counts) {
    TestMesh m = makeTestMesh();
    const float nan = std::numeric_limits<float>::quiet_NaN(),
                inf = std::numeric_limits<float>::infinity();
    std::vector<glm::vec4> tangents(m.positions.size());
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const glm::vec3 n = m.normals[i];
        glm::vec3 t = glm::normalize(glm::cross(glm::vec3(0, 1, 0.1f), n));
        tangents[i] = glm::vec4(t, 1.0f);
    }
    counts = {};
    // Every 7th vertex a NaN normal, every 11th a zero one, every 5th a bad tangent, every 13th
    // a bad uv: as a broken exporter leaves them, scattered.
    for (size_t i = 0; i < m.positions.size(); ++i) {
        if (i % 7 == 3)
            m.normals[i] = glm::vec3(nan, 0, 1), ++counts.nanNormals;
        else if (i % 11 == 4)
            m.normals[i] = glm::vec3(0.0f), ++counts.zeroNormals;
        if (i % 5 == 2)
            tangents[i] = i % 2 ? glm::vec4(inf, 0, 0, 1) : glm::vec4(0, 0, 0, 1),
            ++counts.badTangents;
        if (i % 13 == 6) m.uvs[i] = glm::vec2(nan, inf), ++counts.badUvs;
    }
    Writer w;
    addPlain(w, m);
    w.primitive()["attributes"]["TANGENT"] =
        w.accessor({{"bufferView", w.view(tangents.data(), tangents.size() * 16)},
                    {"componentType", kFloat},
                    {"count", tangents.size()},
                    {"type", "VEC4"}});
    return w.write(dir);
}

fs::path writeDracoScene(const fs::path& dir) {
    const TestMesh m = makeTestMesh();
    const size_t n = m.positions.size();
    draco::Mesh mesh;
    mesh.set_num_points(uint32_t(n));
    auto add = [&](draco::GeometryAttribute::Type type, int comps, const float* data) {
        draco::GeometryAttribute ga;
        ga.Init(type, nullptr, uint8_t(comps), draco::DT_FLOAT32, false,
                int64_t(sizeof(float)) * comps, 0);
        const int id = mesh.AddAttribute(ga, true, uint32_t(n));
        for (size_t i = 0; i < n; ++i)
            mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(uint32_t(i)),
                                                  data + i * size_t(comps));
        return id;
    };
    const int pos = add(draco::GeometryAttribute::POSITION, 3, &m.positions[0].x);
    const int nrm = add(draco::GeometryAttribute::NORMAL, 3, &m.normals[0].x);
    const int tex = add(draco::GeometryAttribute::TEX_COORD, 2, &m.uvs[0].x);
    for (size_t t = 0; t < m.indices.size(); t += 3)
        mesh.AddFace({draco::PointIndex(m.indices[t]), draco::PointIndex(m.indices[t + 1]),
                      draco::PointIndex(m.indices[t + 2])});
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 16);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 12);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 14);
    draco::EncoderBuffer encoded;
    if (!encoder.EncodeMeshToBuffer(mesh, &encoded).ok())
        throw std::runtime_error("draco encoding failed");
    // The counts a real exporter writes: those of the decoded mesh (the encoder may split
    // or reorder vertices).
    draco::DecoderBuffer check;
    check.Init(encoded.data(), encoded.size());
    auto decoded = draco::Decoder().DecodeMeshFromBuffer(&check);
    if (!decoded.ok()) throw std::runtime_error("draco round trip failed");
    const size_t points = decoded.value()->num_points(), faces = decoded.value()->num_faces();

    Writer w;
    const int view = w.view(encoded.data(), encoded.size());
    auto accessor = [&](const char* type, size_t count, int componentType) {
        return w.accessor({{"componentType", componentType}, {"count", count}, {"type", type}});
    };
    json pos0 = {{"componentType", kFloat}, {"count", points}, {"type", "VEC3"}};
    pos0.update(minMax(m.positions));
    json& prim = w.primitive();
    prim["attributes"]["POSITION"] = w.accessor(pos0);
    prim["attributes"]["NORMAL"] = accessor("VEC3", points, kFloat);
    prim["attributes"]["TEXCOORD_0"] = accessor("VEC2", points, kFloat);
    prim["indices"] = accessor("SCALAR", faces * 3, kUInt);
    prim["extensions"]["KHR_draco_mesh_compression"] = {
        {"bufferView", view},
        {"attributes",
         {{"POSITION", mesh.attribute(pos)->unique_id()},
          {"NORMAL", mesh.attribute(nrm)->unique_id()},
          {"TEXCOORD_0", mesh.attribute(tex)->unique_id()}}}};
    w.gltf["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    w.gltf["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    return w.write(dir);
}

fs::path writeMeshoptScene(const fs::path& dir) {
    const TestMesh m = makeTestMesh();
    const size_t n = m.positions.size();
    Writer w;
    // Buffer 1: the fallback, with no bytes of its own (as gltfpack writes it).
    size_t fallbackLength = 0;
    auto compressed = [&](const std::vector<uint8_t>& bytes, size_t count, size_t stride,
                          const char* mode, const char* filter) {
        const int v = w.view(bytes.data(), bytes.size());
        json& view = w.gltf["bufferViews"][size_t(v)];
        json ext = {{"buffer", 0},
                    {"byteOffset", view["byteOffset"]},
                    {"byteLength", bytes.size()},
                    {"byteStride", stride},
                    {"count", count},
                    {"mode", mode}};
        if (filter) ext["filter"] = filter;
        while (fallbackLength % 4)
            ++fallbackLength;
        view = {{"buffer", 1},
                {"byteOffset", fallbackLength},
                {"byteLength", count * stride},
                {"extensions", {{"EXT_meshopt_compression", ext}}}};
        if (std::string(mode) == "ATTRIBUTES") view["byteStride"] = stride;
        fallbackLength += count * stride;
        return v;
    };
    auto encodeVertices = [&](const void* data, size_t stride) {
        std::vector<uint8_t> out(meshopt_encodeVertexBufferBound(n, stride));
        out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), data, n, stride));
        return out;
    };
    // Octahedral normals in 8 bits (stride 4, w = 0).
    std::vector<float> normals4(n * 4, 0.0f);
    for (size_t i = 0; i < n; ++i)
        std::memcpy(&normals4[i * 4], &m.normals[i], 12);
    std::vector<int8_t> octahedral(n * 4);
    meshopt_encodeFilterOct(octahedral.data(), n, 4, 8, normals4.data());
    std::vector<uint8_t> indices(meshopt_encodeIndexBufferBound(m.indices.size(), n));
    indices.resize(meshopt_encodeIndexBuffer(indices.data(), indices.size(), m.indices.data(),
                                             m.indices.size()));

    json pos = {{"bufferView",
                 compressed(encodeVertices(m.positions.data(), 12), n, 12, "ATTRIBUTES", nullptr)},
                {"componentType", kFloat},
                {"count", n},
                {"type", "VEC3"}};
    pos.update(minMax(m.positions));
    json& prim = w.primitive();
    prim["attributes"]["POSITION"] = w.accessor(pos);
    prim["attributes"]["NORMAL"] =
        w.accessor({{"bufferView", compressed(encodeVertices(octahedral.data(), 4), n, 4,
                                              "ATTRIBUTES", "OCTAHEDRAL")},
                    {"componentType", kByte},
                    {"normalized", true},
                    {"count", n},
                    {"type", "VEC3"}});
    prim["attributes"]["TEXCOORD_0"] = w.accessor(
        {{"bufferView", compressed(encodeVertices(m.uvs.data(), 8), n, 8, "ATTRIBUTES", nullptr)},
         {"componentType", kFloat},
         {"count", n},
         {"type", "VEC2"}});
    prim["indices"] =
        w.accessor({{"bufferView", compressed(indices, m.indices.size(), 4, "TRIANGLES", nullptr)},
                    {"componentType", kUInt},
                    {"count", m.indices.size()},
                    {"type", "SCALAR"}});
    w.gltf["buffers"].push_back(
        {{"byteLength", fallbackLength},
         {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
    w.gltf["extensionsUsed"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
    w.gltf["extensionsRequired"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
    return w.write(dir);
}

fs::path writeTextureTransformScene(const fs::path& dir) {
    Writer w;
    addPlain(w, makeTestMesh());
    w.gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]
          ["KHR_texture_transform"] = {
        {"offset", {0.5, 0}}, {"rotation", M_PI / 2}, {"scale", {2, 1}}};
    w.gltf["extensionsUsed"] = {"KHR_texture_transform"};
    return w.write(dir);
}

fs::path writeMaskedScene(const fs::path& dir) {
    Writer w;
    addPlain(w, makeTestMesh());
    json& material = w.gltf["materials"][0];
    material["alphaMode"] = "MASK";
    material["alphaCutoff"] = 0.5;
    material["doubleSided"] = true;
    w.gltf["images"][0]["uri"] = "holes.png";
    // 32 x 32: a hole of radius 5 texels in each 16 x 16 cell (alpha 0 inside, 1 outside, a
    // 2-texel ramp between, so the cutoff's contour is smooth under bilinear filtering and
    // mipmapping), on a colour that varies with the texel (the shading differs per pixel).
    const uint32_t n = 32;
    ImageRGBA holes(n, n);
    for (uint32_t y = 0; y < n; ++y)
        for (uint32_t x = 0; x < n; ++x) {
            const float dx = float(x % 16) + 0.5f - 8.0f, dy = float(y % 16) + 0.5f - 8.0f;
            const float r = std::sqrt(dx * dx + dy * dy);
            float* p = &holes.rgba[(y * n + x) * 4];
            p[0] = 0.9f;
            p[1] = 0.3f + 0.6f * float(x) / float(n);
            p[2] = 0.2f + 0.6f * float(y) / float(n);
            p[3] = std::clamp((r - 4.0f) / 2.0f, 0.0f, 1.0f);
        }
    fs::create_directories(dir);
    if (Status s = writePng((dir / "holes.png").string(), holes, /*keepAlpha=*/true); !s)
        throw std::runtime_error(s.error());
    return w.write(dir);
}

} // namespace tp::test
