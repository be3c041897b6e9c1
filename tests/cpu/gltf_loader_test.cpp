// The glTF loader on the real scenes in shared/scenes, on the glTF-Validator's broken files in
// shared/scenes/negative, and on small files written here (good and broken).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <zlib.h>

#include "core/scene/gltf_internal.h"
#include "core/scene/gltf_loader.h"
#include "tests/cli/hostile_scenes.h"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace tp;

namespace {

fs::path scenesDir() {
    return fs::path(TP_SHARED_SCENES);
}

#define SKIP_WITHOUT_SCENES()                                                                      \
    if (!fs::is_directory(scenesDir()))                                                            \
    GTEST_SKIP() << "shared scenes not found at " << scenesDir() << "; skipping"

struct Loaded {
    Result<Scene> scene;
    std::vector<std::string> warnings;
    double seconds;
};

Loaded load(const fs::path& path, GltfLoadOptions options = {}) {
    std::vector<std::string> warnings;
    options.warnings = &warnings;
    auto t0 = std::chrono::steady_clock::now();
    Result<Scene> scene = loadGltf(path.string(), options);
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return {std::move(scene), std::move(warnings), s};
}

bool anyContains(const std::vector<std::string>& lines, const std::string& text) {
    for (const std::string& l : lines)
        if (l.find(text) != std::string::npos) return true;
    return false;
}

void expectOneLineError(const Loaded& l, const fs::path& path, const std::string& reason) {
    ASSERT_FALSE(l.scene.ok()) << path;
    const std::string& e = l.scene.error();
    EXPECT_NE(e.find(path.filename().string()), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    EXPECT_NE(e.find(reason), std::string::npos) << "expected '" << reason << "' in: " << e;
}

void expectSaneAttributes(const Scene& scene) {
    for (const Mesh& m : scene.meshes) {
        size_t n = m.positions.size();
        ASSERT_EQ(m.normals.size(), n);
        ASSERT_EQ(m.tangents.size(), n);
        ASSERT_EQ(m.uvs.size(), n);
        ASSERT_EQ(m.colors.size(), n);
        ASSERT_EQ(m.indices.size() % 3, 0u);
        for (uint32_t i : m.indices)
            ASSERT_LT(i, n);
        ASSERT_LT(m.material, scene.materials.size());
    }
}

// Generated tangents must be unit length, perpendicular to the normal, w = +-1.
void expectOrthonormalTangents(const Scene& scene) {
    size_t bad = 0;
    for (const Mesh& m : scene.meshes)
        for (size_t i = 0; i < m.positions.size(); ++i) {
            glm::vec3 t(m.tangents[i]);
            bad += std::abs(glm::length(t) - 1.0f) > 1e-3f ||
                   std::abs(glm::dot(t, m.normals[i])) > 1e-3f ||
                   std::abs(std::abs(m.tangents[i].w) - 1.0f) > 0.0f;
        }
    EXPECT_EQ(bad, 0u);
}

// ---- Real scenes ----------------------------------------------------------------------------

TEST(GltfScenes, DamagedHelmetGltfAndGlbAgree) {
    SKIP_WITHOUT_SCENES();
    Loaded a = load(scenesDir() / "DamagedHelmet/glTF/DamagedHelmet.gltf");
    Loaded b = load(scenesDir() / "DamagedHelmet/glTF-Binary/DamagedHelmet.glb");
    ASSERT_TRUE(a.scene.ok()) << a.scene.error();
    ASSERT_TRUE(b.scene.ok()) << b.scene.error();
    std::printf("[ timing ] DamagedHelmet .gltf %.3f s, .glb %.3f s\n", a.seconds, b.seconds);
    for (Loaded* l : {&a, &b}) {
        const Scene& s = *l->scene;
        EXPECT_EQ(s.triangleCount(), 15452u);
        EXPECT_TRUE(l->warnings.empty()) << l->warnings.front();
        expectSaneAttributes(s);
        expectOrthonormalTangents(s);
        ASSERT_EQ(s.materials.size(), 1u);
        const Material& m = s.materials[0];
        for (int32_t t : {m.baseColorTexture, m.metallicRoughnessTexture, m.normalTexture,
                          m.occlusionTexture, m.emissiveTexture})
            ASSERT_NE(t, kNoTexture);
        EXPECT_TRUE(s.textures[size_t(m.baseColorTexture)].srgb);
        EXPECT_TRUE(s.textures[size_t(m.emissiveTexture)].srgb);
        EXPECT_FALSE(s.textures[size_t(m.normalTexture)].srgb);
        EXPECT_FALSE(s.textures[size_t(m.metallicRoughnessTexture)].srgb);
        EXPECT_EQ(s.textures.size(), 5u);
        for (const Texture& t : s.textures) {
            EXPECT_EQ(t.width, 2048u);
            EXPECT_EQ(t.rgba8.size(), size_t(t.width) * t.height * 4);
        }
        EXPECT_FALSE(s.bounds.empty());
        EXPECT_EQ(s.source,
                  l == &a ? (scenesDir() / "DamagedHelmet/glTF/DamagedHelmet.gltf").string()
                          : (scenesDir() / "DamagedHelmet/glTF-Binary/DamagedHelmet.glb").string());
        // No camera in the file: framed from the bounds, looking at their centre.
        EXPECT_LT(glm::length(s.camera.target - s.bounds.center()), 1e-4f);
        EXPECT_EQ(s.camera.zfar, 0.0f);
    }
    EXPECT_EQ(a.scene->vertexCount(), b.scene->vertexCount());
}

TEST(GltfScenes, AlphaBlendModes) {
    SKIP_WITHOUT_SCENES();
    Loaded l = load(scenesDir() / "AlphaBlendModeTest/glTF/AlphaBlendModeTest.gltf");
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    std::printf("[ timing ] AlphaBlendModeTest %.3f s\n", l.seconds);
    expectSaneAttributes(*l.scene);
    std::map<std::string, const Material*> byName;
    for (const Material& m : l.scene->materials)
        byName[m.name] = &m;
    ASSERT_TRUE(byName.count("MatBlend") && byName.count("MatCutoff25") &&
                byName.count("MatCutoff75") && byName.count("MatCutoffDefault") &&
                byName.count("MatOpaque") && byName.count("MatBed"));
    EXPECT_EQ(byName["MatBlend"]->alphaMode, AlphaMode::Blend);
    EXPECT_EQ(byName["MatCutoff25"]->alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(byName["MatCutoff25"]->alphaCutoff, 0.25f);
    EXPECT_EQ(byName["MatCutoff75"]->alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(byName["MatCutoff75"]->alphaCutoff, 0.75f);
    EXPECT_EQ(byName["MatCutoffDefault"]->alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(byName["MatCutoffDefault"]->alphaCutoff, 0.5f);
    EXPECT_EQ(byName["MatOpaque"]->alphaMode, AlphaMode::Opaque);
    EXPECT_TRUE(byName["MatBlend"]->doubleSided);
    EXPECT_FALSE(byName["MatBed"]->doubleSided);
    EXPECT_EQ(l.scene->triangleCount(), 61u);
}

TEST(GltfScenes, MetalRoughSpheresNoTextures) {
    SKIP_WITHOUT_SCENES();
    Loaded l =
        load(scenesDir() / "MetalRoughSpheresNoTextures/glTF/MetalRoughSpheresNoTextures.gltf");
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    std::printf("[ timing ] MetalRoughSpheresNoTextures %.3f s\n", l.seconds);
    EXPECT_EQ(l.scene->triangleCount(), 1040409u);
    // 98 from the file, plus the default material for the 25 primitives that name none.
    ASSERT_EQ(l.scene->materials.size(), 99u);
    EXPECT_EQ(l.scene->materials.back().name, "default");
    EXPECT_TRUE(l.scene->textures.empty());
    expectSaneAttributes(*l.scene);
}

TEST(GltfScenes, NormalTangentMirrorKeepsNegativeW) {
    SKIP_WITHOUT_SCENES();
    Loaded l = load(scenesDir() / "NormalTangentMirrorTest/glTF/NormalTangentMirrorTest.gltf");
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    std::printf("[ timing ] NormalTangentMirrorTest %.3f s\n", l.seconds);
    expectSaneAttributes(*l.scene);
    EXPECT_EQ(l.scene->triangleCount(), 5240u);
    size_t negative = 0, positive = 0;
    for (const Mesh& m : l.scene->meshes)
        for (const glm::vec4& t : m.tangents)
            (t.w < 0 ? negative : positive)++;
    EXPECT_GT(negative, 0u);
    EXPECT_GT(positive, 0u);

    // The file's tangents were made by MikkTSpace: ours from the same uvs must agree on the
    // handedness (this checks the v-flip convention) and roughly on the direction.
    size_t agreeW = 0, agreeDir = 0, total = 0;
    for (const Mesh& m : l.scene->meshes) {
        std::vector<glm::vec4> ours;
        gltf::makeTangents(m.positions, m.normals, m.uvs, m.indices, ours);
        for (size_t i = 0; i < ours.size(); ++i, ++total) {
            agreeW += ours[i].w == m.tangents[i].w;
            agreeDir += glm::dot(glm::vec3(ours[i]), glm::vec3(m.tangents[i])) > 0.9f;
        }
    }
    EXPECT_GT(double(agreeW), 0.98 * double(total));
    EXPECT_GT(double(agreeDir), 0.9 * double(total));
}

TEST(GltfScenes, VertexColors) {
    SKIP_WITHOUT_SCENES();
    for (const char* file : {"VertexColorTest/glTF/VertexColorTest.gltf",
                             "VertexColorTest/glTF-Binary/VertexColorTest.glb"}) {
        Loaded l = load(scenesDir() / file);
        ASSERT_TRUE(l.scene.ok()) << l.scene.error();
        std::printf("[ timing ] %s %.3f s\n", file, l.seconds);
        expectSaneAttributes(*l.scene);
        EXPECT_EQ(l.scene->triangleCount(), 36u);
        size_t coloured = 0;
        for (const Mesh& m : l.scene->meshes)
            for (const glm::vec4& c : m.colors)
                coloured += c != glm::vec4(1.0f);
        EXPECT_GT(coloured, 0u) << file;
        EXPECT_TRUE(analyzeScene(*l.scene, 1).vertexColors);
    }
}

// ---- The glTF-Validator's broken files ------------------------------------------------------

TEST(GltfNegative, EveryBrokenFileFailsCleanly) {
    SKIP_WITHOUT_SCENES();
    const fs::path dir = scenesDir() / "negative";
    if (!fs::is_directory(dir)) GTEST_SKIP() << dir << " not found";
    // What the error must mention (negative/MANIFEST.txt says what each file breaks).
    const std::map<std::string, std::string> reasons = {
        {"glb/empty_file.glb", "empty"},
        {"glb/invalid_magic.glb", "magic"},
        {"glb/length_mismatch.glb", "length"},
        {"glb/truncated_chunk_header.glb", "chunk header"},
        {"json/empty_file.gltf", "empty"},
        {"json/invalid_syntax.gltf", "malformed JSON"},
        {"asset/1_0_version.gltf", "\"1.0\""},
        {"root/undefined_used_extensions.gltf", "KHR_extension"},
        {"buffer/not_found.gltf", "not found"},
        {"buffer/non_relative_uri.gltf", "http://example.com/buffer.bin"},
        {"image/not_found.gltf", "nothing to draw"},
        {"accessor/unresolved_bufferviews.gltf", "bufferView 0 does not exist"},
        {"mesh_data/index_buffer_oob.gltf", "out of range"},
        {"node/node_loop.gltf", "cycle"},
    };
    size_t seen = 0;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        std::string ext = entry.path().extension().string();
        if (ext != ".gltf" && ext != ".glb") continue;
        ++seen;
        std::string rel = entry.path().lexically_relative(dir).generic_string();
        SCOPED_TRACE(rel);
        Loaded l = load(entry.path());
        std::printf("[ negative ] %-40s -> %s\n", rel.c_str(),
                    l.scene.ok() ? "loaded" : l.scene.error().c_str());
        auto it = reasons.find(rel);
        ASSERT_NE(it, reasons.end()) << "a new negative file: add it here";
        if (rel == "buffer/non_relative_uri.gltf") {
            // Only a warning for the validator; the loader must still refuse to fetch it
            // (it is a buffer, so refusing it is an error).
            if (l.scene.ok())
                EXPECT_TRUE(anyContains(l.warnings, it->second));
            else
                expectOneLineError(l, entry.path(), it->second);
            continue;
        }
        expectOneLineError(l, entry.path(), it->second);
        if (rel == "image/not_found.gltf") {
            EXPECT_TRUE(anyContains(l.warnings, "not_found.png"));
        }
    }
    EXPECT_EQ(seen, 14u);
}

// ---- Generated files ------------------------------------------------------------------------

class GltfGenerated : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("triptych_gltf_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "scene");
        // One triangle in the z = 0 plane, counter-clockwise seen from +z, and its indices.
        bin_ = hostile::triangleBin();
        gltf_ = hostile::triangleJson();
    }
    void TearDown() override { fs::remove_all(dir_); }

    // Appends bytes to the buffer (4-aligned), adds a bufferView for them; returns its index.
    int addView(const void* data, size_t size) {
        while (bin_.size() % 4)
            bin_.push_back(0);
        size_t offset = bin_.size();
        bin_.insert(bin_.end(), (const uint8_t*)data, (const uint8_t*)data + size);
        gltf_["bufferViews"].push_back(
            {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}});
        gltf_["buffers"][0]["byteLength"] = bin_.size();
        return int(gltf_["bufferViews"].size()) - 1;
    }
    int addAccessor(json accessor) {
        gltf_["accessors"].push_back(accessor);
        return int(gltf_["accessors"].size()) - 1;
    }
    fs::path write(const std::string& name = "scene.gltf") {
        fs::path path = dir_ / "scene" / name;
        std::ofstream(path) << gltf_.dump(1);
        std::ofstream(dir_ / "scene" / "tri.bin", std::ios::binary)
            .write((const char*)bin_.data(), std::streamsize(bin_.size()));
        return path;
    }

    fs::path dir_;
    json gltf_;
    std::vector<uint8_t> bin_;
};

TEST_F(GltfGenerated, TriangleGetsFlatNormalsDefaultsAndACamera) {
    Loaded l = load(write());
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    const Scene& s = *l.scene;
    expectSaneAttributes(s);
    expectOrthonormalTangents(s);
    ASSERT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.materials.size(), 1u); // the default
    const Mesh& m = s.meshes[0];
    EXPECT_EQ(m.indices.size(), 3u);
    for (size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(glm::length(m.normals[i] - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
        EXPECT_EQ(m.uvs[i], glm::vec2(0.0f));
        EXPECT_EQ(m.colors[i], glm::vec4(1.0f));
    }
    EXPECT_EQ(s.camera.target, s.bounds.center());
    glm::vec3 dir = glm::normalize(s.camera.position - s.camera.target);
    EXPECT_NEAR(glm::length(dir - glm::normalize(glm::vec3(0.3f, 0.35f, 1.0f))), 0.0f, 1e-5f);
    EXPECT_GT(s.camera.znear, 0.0f);
}

TEST_F(GltfGenerated, SmoothNormalsOnRequest) {
    GltfLoadOptions options;
    options.smoothMissingNormals = true;
    Loaded l = load(write(), options);
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    EXPECT_EQ(l.scene->meshes[0].positions.size(), 3u);
    EXPECT_NEAR(l.scene->meshes[0].normals[0].z, 1.0f, 1e-6f);
}

TEST_F(GltfGenerated, InstancesMirrorsAndTransforms) {
    float normals[9] = {0, 0, 1, 0, 0, 1, 0, 0, 1};
    float tangents[12] = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
    gltf_["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] =
        addAccessor({{"bufferView", addView(normals, 36)},
                     {"componentType", 5126},
                     {"count", 3},
                     {"type", "VEC3"}});
    gltf_["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] =
        addAccessor({{"bufferView", addView(tangents, 48)},
                     {"componentType", 5126},
                     {"count", 3},
                     {"type", "VEC4"}});
    gltf_["nodes"] = json::parse(R"([
        {"children": [1, 2], "translation": [0, 0, 5]},
        {"mesh": 0, "translation": [10, 0, 0]},
        {"mesh": 0, "scale": [-1, 1, 1]}])");
    Loaded l = load(write());
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    ASSERT_EQ(l.scene->meshes.size(), 2u);
    const Mesh& plain = l.scene->meshes[0];
    const Mesh& mirrored = l.scene->meshes[1];
    EXPECT_EQ(plain.positions[1], glm::vec3(11, 0, 5));
    EXPECT_EQ(mirrored.positions[1], glm::vec3(-1, 0, 5));
    for (const Mesh* m : {&plain, &mirrored}) {
        // The winding still agrees with the normal: front faces stay front faces.
        glm::vec3 face = glm::cross(m->positions[m->indices[1]] - m->positions[m->indices[0]],
                                    m->positions[m->indices[2]] - m->positions[m->indices[0]]);
        EXPECT_GT(glm::dot(face, m->normals[0]), 0.0f);
        EXPECT_NEAR(m->normals[0].z, 1.0f, 1e-6f);
    }
    EXPECT_EQ(plain.tangents[0], glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(mirrored.tangents[0], glm::vec4(-1, 0, 0, -1)); // mirrored: w flips
}

TEST_F(GltfGenerated, StripsSparseColorsAndDataUris) {
    // A strip of 4 vertices (2 triangles); vertex 3's position comes from a sparse override.
    float positions[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 9, 9, 9};
    uint8_t sparseIndex[4] = {3, 0, 0, 0};
    float sparseValue[3] = {1, 1, 0};
    uint8_t colors[12] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    json accessor = {{"bufferView", addView(positions, 48)},
                     {"componentType", 5126},
                     {"count", 4},
                     {"type", "VEC3"}};
    accessor["sparse"] = {
        {"count", 1},
        {"indices", {{"bufferView", addView(sparseIndex, 1)}, {"componentType", 5121}}},
        {"values", {{"bufferView", addView(sparseValue, 12)}}}};
    json& prim = gltf_["meshes"][0]["primitives"][0];
    prim = {{"attributes", {{"POSITION", addAccessor(accessor)}}}, {"mode", 5}};
    prim["attributes"]["COLOR_0"] = addAccessor({{"bufferView", addView(colors, 12)},
                                                 {"componentType", 5121},
                                                 {"normalized", true},
                                                 {"count", 4},
                                                 {"type", "VEC3"}});
    // The whole buffer as a data URI.
    static const char* b64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string encoded;
    for (size_t i = 0; i < bin_.size(); i += 3) {
        size_t n = std::min<size_t>(3, bin_.size() - i);
        uint32_t v =
            uint32_t(bin_[i]) << 16 | (n > 1 ? bin_[i + 1] << 8 : 0) | (n > 2 ? bin_[i + 2] : 0);
        encoded += b64[v >> 18 & 63];
        encoded += b64[v >> 12 & 63];
        encoded += n > 1 ? b64[v >> 6 & 63] : '=';
        encoded += n > 2 ? b64[v & 63] : '=';
    }
    gltf_["buffers"][0]["uri"] = "data:application/octet-stream;base64," + encoded;
    Loaded l = load(write());
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    const Mesh& m = l.scene->meshes[0];
    ASSERT_EQ(m.indices.size(), 6u);
    EXPECT_EQ(m.positions.size(), 6u); // flat normals: one vertex per corner
    EXPECT_EQ(m.positions[m.indices[4]], glm::vec3(1, 1, 0)) << "sparse override";
    for (size_t i = 0; i < m.normals.size(); ++i)
        EXPECT_NEAR(m.normals[i].z, 1.0f, 1e-6f) << i;
    EXPECT_EQ(m.colors[0], glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(m.colors[1], glm::vec4(0, 1, 0, 1));
}

TEST_F(GltfGenerated, LightsEmissiveStrengthAndFileCamera) {
    gltf_["extensionsUsed"] = {"KHR_lights_punctual", "KHR_materials_emissive_strength"};
    gltf_["extensions"]["KHR_lights_punctual"]["lights"] = json::parse(R"([
        {"type": "point", "intensity": 10, "color": [1, 0.5, 0.5]},
        {"type": "spot", "intensity": 2, "range": 7, "spot": {"outerConeAngle": 0.5}}])");
    gltf_["materials"] = json::parse(R"([{"emissiveFactor": [1, 0.5, 0],
        "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4}}}])");
    gltf_["meshes"][0]["primitives"][0]["material"] = 0;
    gltf_["cameras"] =
        json::parse(R"([{"type": "perspective", "perspective": {"yfov": 0.6, "znear": 0.1}}])");
    gltf_["scenes"][0]["nodes"] = {0, 1, 2, 3};
    // Spot: rotated -90 degrees about +x, so local -z points down (-y).
    gltf_["nodes"] = json::parse(R"([{"mesh": 0},
        {"translation": [1, 2, 3], "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"rotation": [-0.7071068, 0, 0, 0.7071068], "extensions": {"KHR_lights_punctual": {"light": 1}}},
        {"translation": [0, 0, 4], "camera": 0}])");
    Loaded l = load(write());
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    EXPECT_TRUE(l.warnings.empty());
    const Scene& s = *l.scene;
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(s.materials[0].emissiveFactor, glm::vec3(4, 2, 0));
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_EQ(s.lights[0].type, LightType::Point);
    EXPECT_EQ(s.lights[0].position, glm::vec3(1, 2, 3));
    EXPECT_NEAR(s.lights[0].range, std::sqrt(10.0f / 1e-3f), 1e-2f); // I * max(colour) / d^2 = 1e-3
    EXPECT_EQ(s.lights[1].type, LightType::Spot);
    EXPECT_FLOAT_EQ(s.lights[1].range, 7.0f);
    EXPECT_FLOAT_EQ(s.lights[1].outerConeAngle, 0.5f);
    EXPECT_NEAR(glm::length(s.lights[1].direction - glm::vec3(0, -1, 0)), 0.0f, 1e-5f);
    EXPECT_EQ(s.camera.position, glm::vec3(0, 0, 4));
    EXPECT_NEAR(s.camera.yfov, 0.6f, 1e-6f);
    EXPECT_FLOAT_EQ(s.camera.znear, 0.1f);
    EXPECT_LT(s.camera.target.z, 4.0f);
}

// A PNG written by hand (stored deflate blocks), so the test needs no encoder; zlib only for
// the chunks' CRC.
std::vector<uint8_t> makePng(uint32_t w, uint32_t h, uint8_t bitDepth, uint8_t colorType,
                             const std::vector<uint8_t>& raw /* filter bytes included */) {
    std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    auto be32 = [](std::vector<uint8_t>& v, uint32_t x) {
        for (int s = 24; s >= 0; s -= 8)
            v.push_back(uint8_t(x >> s));
    };
    auto chunk = [&](const char* type, const std::vector<uint8_t>& data) {
        be32(png, uint32_t(data.size()));
        std::vector<uint8_t> body(type, type + 4);
        body.insert(body.end(), data.begin(), data.end());
        png.insert(png.end(), body.begin(), body.end());
        be32(png, uint32_t(crc32(0, body.data(), uInt(body.size()))));
    };
    std::vector<uint8_t> ihdr;
    be32(ihdr, w);
    be32(ihdr, h);
    ihdr.insert(ihdr.end(), {bitDepth, colorType, 0, 0, 0});
    chunk("IHDR", ihdr);
    std::vector<uint8_t> z = {0x78,
                              0x01,
                              0x01,
                              uint8_t(raw.size()),
                              uint8_t(raw.size() >> 8),
                              uint8_t(~raw.size()),
                              uint8_t(~raw.size() >> 8)};
    z.insert(z.end(), raw.begin(), raw.end());
    uint32_t a = 1, b = 0;
    for (uint8_t x : raw)
        a = (a + x) % 65521, b = (b + a) % 65521;
    be32(z, b << 16 | a);
    chunk("IDAT", z);
    chunk("IEND", {});
    return png;
}

TEST_F(GltfGenerated, TexturesDecodeDedupAndPlaceholders) {
    // A 2x1 16-bit grey PNG, used by base colour (sRGB) and occlusion (linear): two textures.
    std::vector<uint8_t> png = makePng(2, 1, 16, 0, {0, 0xFF, 0xFF, 0x80, 0x00});
    std::ofstream(dir_ / "scene" / "grey16.png", std::ios::binary)
        .write((const char*)png.data(), std::streamsize(png.size()));
    gltf_["images"] = json::parse(R"([{"uri": "grey16.png"}, {"uri": "missing.png"},
        {"uri": "../outside.png"}, {"uri": "file:///etc/passwd"}])");
    gltf_["textures"] =
        json::parse(R"([{"source": 0}, {"source": 1}, {"source": 2}, {"source": 3}])");
    gltf_["materials"] = json::parse(R"([
        {"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}, "occlusionTexture": {"index": 0}},
        {"pbrMetallicRoughness": {"baseColorTexture": {"index": 1}, "metallicRoughnessTexture": {"index": 2}},
         "normalTexture": {"index": 3}, "emissiveTexture": {"index": 0}}])");
    gltf_["meshes"][0]["primitives"][0]["material"] = 1;
    Loaded l = load(write());
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    const Scene& s = *l.scene;
    EXPECT_TRUE(anyContains(l.warnings, "missing.png"));
    EXPECT_TRUE(anyContains(l.warnings, "../outside.png"));
    EXPECT_TRUE(anyContains(l.warnings, "file:///etc/passwd"));
    for (const std::string& w : l.warnings)
        EXPECT_EQ(w.find('\n'), std::string::npos);
    const Material& a = s.materials[0];
    const Material& b = s.materials[1];
    const Texture& base = s.textures[size_t(a.baseColorTexture)];
    EXPECT_TRUE(base.srgb);
    ASSERT_EQ(base.width, 2u);
    EXPECT_EQ(base.rgba8, (std::vector<uint8_t>{255, 255, 255, 255, 128, 128, 128, 255}));
    EXPECT_NE(a.occlusionTexture, a.baseColorTexture); // same image, linear
    EXPECT_FALSE(s.textures[size_t(a.occlusionTexture)].srgb);
    EXPECT_EQ(b.emissiveTexture, a.baseColorTexture); // (image, sRGB) deduplicated
    const Texture& magenta = s.textures[size_t(b.baseColorTexture)];
    EXPECT_EQ(magenta.rgba8, (std::vector<uint8_t>{255, 0, 255, 255}));
    EXPECT_EQ(s.textures[size_t(b.normalTexture)].rgba8,
              (std::vector<uint8_t>{128, 128, 255, 255}));
    EXPECT_EQ(s.textures[size_t(b.metallicRoughnessTexture)].rgba8,
              (std::vector<uint8_t>{255, 255, 255, 255}));
    // The normal-mapped primitive got tangents from its (all-zero) uvs: degenerate, so any
    // perpendicular one.
    expectOrthonormalTangents(s);
}

TEST_F(GltfGenerated, HugeTextureIsAnError) {
    std::vector<uint8_t> png = makePng(20000, 1, 8, 0, {});
    png.resize(33); // the header is all the loader may look at
    std::ofstream(dir_ / "scene" / "huge.png", std::ios::binary)
        .write((const char*)png.data(), std::streamsize(png.size()));
    gltf_["images"] = json::parse(R"([{"uri": "huge.png"}])");
    gltf_["textures"] = json::parse(R"([{"source": 0}])");
    gltf_["materials"] =
        json::parse(R"([{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])");
    fs::path path = write();
    expectOneLineError(load(path), path, "over the 16384 limit");
}

TEST_F(GltfGenerated, MalformedJson) {
    fs::path path = dir_ / "scene" / "broken.gltf";
    std::ofstream(path) << R"({"asset": {"version": "2.0"}, "nodes": [)";
    expectOneLineError(load(path), path, "malformed JSON");
}

TEST_F(GltfGenerated, MissingFile) {
    fs::path path = dir_ / "scene" / "nothing.gltf";
    expectOneLineError(load(path), path, "not found");
}

TEST_F(GltfGenerated, TruncatedBuffer) {
    fs::path path = write();
    fs::resize_file(dir_ / "scene" / "tri.bin", 20);
    expectOneLineError(load(path), path, "truncated");
}

TEST_F(GltfGenerated, AccessorOutOfRange) {
    gltf_["accessors"][0]["count"] = 300;
    fs::path path = write();
    expectOneLineError(load(path), path, "accessor 0");
}

TEST_F(GltfGenerated, AbsurdCountIsAnError) {
    gltf_["accessors"][0].erase("bufferView"); // zeros: no bytes in the file bound the count
    gltf_["accessors"][0]["count"] = (1 << 28) + 1;
    fs::path path = write();
    expectOneLineError(load(path), path, "absurd");
}

TEST_F(GltfGenerated, BufferViewOutOfRange) {
    gltf_["bufferViews"][1]["byteLength"] = 4000;
    fs::path path = write();
    expectOneLineError(load(path), path, "outside its buffer");
}

TEST_F(GltfGenerated, IndexOutOfRange) {
    uint16_t bad[3] = {0, 1, 7};
    std::memcpy(bin_.data() + 36, bad, 6);
    fs::path path = write();
    expectOneLineError(load(path), path, "index 7 at position 2 is out of range");
}

TEST_F(GltfGenerated, WrongComponentType) {
    gltf_["accessors"][0]["componentType"] = 5125; // unsigned int positions
    fs::path path = write();
    expectOneLineError(load(path), path, "POSITION");
}

TEST_F(GltfGenerated, RequiredUnknownExtension) {
    gltf_["extensionsUsed"] = {"EXT_made_up"};
    gltf_["extensionsRequired"] = {"EXT_made_up"};
    fs::path path = write();
    expectOneLineError(load(path), path, "EXT_made_up");
}

TEST_F(GltfGenerated, UsedUnsupportedExtensionWarns) {
    gltf_["extensionsUsed"] = {"KHR_materials_sheen", "KHR_materials_clearcoat",
                               "KHR_texture_transform"};
    Loaded l = load(write());
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    EXPECT_TRUE(anyContains(l.warnings, "KHR_materials_sheen"));
    EXPECT_TRUE(anyContains(l.warnings, "KHR_materials_clearcoat"));
    EXPECT_FALSE(anyContains(l.warnings, "KHR_texture_transform")); // read since issue 14
}

TEST_F(GltfGenerated, BufferUriThatLeavesTheFolder) {
    std::ofstream(dir_ / "outside.bin", std::ios::binary)
        .write((const char*)bin_.data(), std::streamsize(bin_.size()));
    for (const std::string& uri : std::vector<std::string>{
             "../outside.bin", "sub/../../outside.bin", "%2E%2E/outside.bin",
             (dir_ / "outside.bin").string(), "file:///etc/passwd", "http://example.com/tri.bin"}) {
        gltf_["buffers"][0]["uri"] = uri;
        fs::path path = write();
        Loaded l = load(path);
        expectOneLineError(l, path, "refusing to read it");
    }
}

TEST_F(GltfGenerated, NodeCycleAndBadNodeReferences) {
    gltf_["nodes"] = json::parse(R"([{"mesh": 0, "children": [1]}, {"children": [0]}])");
    fs::path path = write();
    expectOneLineError(load(path), path, "cycle");
    gltf_["nodes"] = json::parse(R"([{"children": [2]}, {"children": [2]}, {"mesh": 0}])");
    gltf_["scenes"][0]["nodes"] = {0, 1};
    expectOneLineError(load(write()), path, "more than one parent");
    gltf_["scenes"][0]["nodes"] = {0};
    gltf_["nodes"] = json::parse(R"([{"mesh": 3}])");
    expectOneLineError(load(write()), path, "mesh 3 does not exist");
}

TEST_F(GltfGenerated, GlbHeaderChecks) {
    fs::path path = dir_ / "scene" / "bad.glb";
    std::string text = R"({"asset":{"version":"2.0"}})";
    while (text.size() % 4)
        text += ' ';
    std::vector<uint8_t> glb(20 + text.size());
    uint32_t header[5] = {0x46546C67u, 2, uint32_t(glb.size()), uint32_t(text.size()), 0x4E4F534Au};
    std::memcpy(glb.data(), header, 20);
    std::memcpy(glb.data() + 20, text.data(), text.size());
    auto writeGlb = [&](const std::vector<uint8_t>& bytes) {
        std::ofstream(path, std::ios::binary)
            .write((const char*)bytes.data(), std::streamsize(bytes.size()));
    };
    writeGlb(glb);
    expectOneLineError(load(path), path, "no meshes"); // a well-formed GLB with nothing in it
    std::vector<uint8_t> longer = glb;
    longer.resize(glb.size() + 4);
    writeGlb(longer);
    expectOneLineError(load(path), path, "length");
    std::vector<uint8_t> badChunk = glb;
    uint32_t tooLong = 4000;
    std::memcpy(badChunk.data() + 12, &tooLong, 4);
    writeGlb(badChunk);
    expectOneLineError(load(path), path, "JSON chunk");
}

// ---- Repairs (docs/hostile_input.md, "Repaired, not refused") ------------------------------

// The triangle with NORMAL (NaN at 0, zero-length at 1), TANGENT (infinite at 2), TEXCOORD_0
// (NaN at 1) and COLOR_0 (NaN at 0): every one repaired, one line and one record each.
TEST_F(GltfGenerated, NonFiniteAttributesAreRepairedLoudly) {
    const float nan = std::nanf(""), inf = INFINITY;
    float normals[9] = {nan, 0, 1, 0, 0, 0, 0, 0, 1};
    float tangents[12] = {1, 0, 0, 1, 1, 0, 0, -1, inf, 0, 0, 1};
    float uvs[6] = {0, 0, nan, 1, 1, 1};
    float colors[12] = {nan, 1, 1, 1, 0.5f, 0.5f, 0.5f, 1, 1, 1, 1, 1};
    auto& attributes = gltf_["meshes"][0]["primitives"][0]["attributes"];
    auto add = [&](const void* data, size_t size, const char* type) {
        return addAccessor({{"bufferView", addView(data, size)},
                            {"componentType", 5126},
                            {"count", 3},
                            {"type", type}});
    };
    attributes["NORMAL"] = add(normals, sizeof normals, "VEC3");
    attributes["TANGENT"] = add(tangents, sizeof tangents, "VEC4");
    attributes["TEXCOORD_0"] = add(uvs, sizeof uvs, "VEC2");
    attributes["COLOR_0"] = add(colors, sizeof colors, "VEC4");
    fs::path path = write();
    Loaded l = load(path);
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    const Scene& s = *l.scene;
    expectSaneAttributes(s);
    const Mesh& m = s.meshes[0];
    for (size_t i = 0; i < 3; ++i) {
        // The triangle's face normal, +z.
        EXPECT_NEAR(glm::length(m.normals[i] - glm::vec3(0, 0, 1)), 0.0f, 1e-6f) << i;
        EXPECT_TRUE(std::isfinite(glm::dot(m.tangents[i], m.tangents[i]))) << i;
        EXPECT_NEAR(glm::length(glm::vec3(m.tangents[i])), 1.0f, 1e-5f) << i;
    }
    EXPECT_EQ(m.tangents[0], glm::vec4(1, 0, 0, 1)); // good ones are kept
    EXPECT_EQ(m.tangents[1].w, -1.0f);
    EXPECT_EQ(m.uvs[1], glm::vec2(0.0f));
    EXPECT_EQ(m.uvs[2], glm::vec2(1.0f));
    EXPECT_EQ(m.colors[0], glm::vec4(1.0f));
    EXPECT_EQ(m.colors[1], glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
    ASSERT_EQ(s.repairs.size(), 4u);
    std::map<std::string, SceneRepair> byName;
    for (const SceneRepair& r : s.repairs)
        byName[r.attribute] = r;
    EXPECT_EQ(byName["NORMAL"].count, 2u);
    EXPECT_EQ(byName["NORMAL"].total, 3u);
    EXPECT_EQ(byName["NORMAL"].accessor, int(attributes["NORMAL"]));
    EXPECT_EQ(byName["TANGENT"].count, 1u);
    EXPECT_EQ(byName["TEXCOORD_0"].count, 1u);
    EXPECT_EQ(byName["COLOR_0"].count, 1u);
    ASSERT_EQ(l.warnings.size(), 4u);
    for (const std::string& w : l.warnings) {
        EXPECT_EQ(w.find('\n'), std::string::npos) << w;
        EXPECT_NE(w.find("scene.gltf: repaired "), std::string::npos) << w;
    }
    EXPECT_TRUE(anyContains(l.warnings, "repaired NORMAL accessor " +
                                            std::to_string(int(attributes["NORMAL"])) +
                                            ": 2 of 3 values"));

    // --strict: today's refusal, naming the attribute and accessor.
    GltfLoadOptions strict;
    strict.strict = true;
    expectOneLineError(load(path, strict), path, "NORMAL accessor");
}

TEST_F(GltfGenerated, RepairedNormalsAreTheFaceNormalsAroundTheVertex) {
    // Two triangles of a quad folded 90 degrees along the x axis, sharing vertices 0 and 1:
    // the shared vertices' repaired normal is the area-weighted mean of +z and +y.
    float positions[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, -1};
    uint16_t indices[6] = {0, 1, 2, 0, 1, 3};
    const float nan = std::nanf("");
    float normals[12] = {nan, nan, nan, nan, nan, nan, 0, 0, 1, 0, 1, 0};
    gltf_["accessors"][0] = {{"bufferView", addView(positions, sizeof positions)},
                             {"componentType", 5126},
                             {"count", 4},
                             {"type", "VEC3"},
                             {"min", {0, 0, -1}},
                             {"max", {1, 1, 0}}};
    gltf_["accessors"][1] = {{"bufferView", addView(indices, sizeof indices)},
                             {"componentType", 5123},
                             {"count", 6},
                             {"type", "SCALAR"}};
    gltf_["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] =
        addAccessor({{"bufferView", addView(normals, sizeof normals)},
                     {"componentType", 5126},
                     {"count", 4},
                     {"type", "VEC3"}});
    Loaded l = load(write());
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    const Mesh& m = l.scene->meshes[0];
    const glm::vec3 mean = glm::normalize(glm::vec3(0, 1, 1));
    EXPECT_NEAR(glm::length(m.normals[0] - mean), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(m.normals[1] - mean), 0.0f, 1e-6f);
    EXPECT_EQ(m.normals[2], glm::vec3(0, 0, 1));
    EXPECT_EQ(m.normals[3], glm::vec3(0, 1, 0));
    ASSERT_EQ(l.scene->repairs.size(), 1u);
    EXPECT_EQ(l.scene->repairs[0].count, 2u);
}

TEST_F(GltfGenerated, NonFinitePositionsStayAnError) {
    float positions[9] = {0, 0, 0, 1, 0, 0, 0, INFINITY, 0};
    gltf_["accessors"][0]["bufferView"] = addView(positions, sizeof positions);
    fs::path path = write();
    expectOneLineError(load(path), path, "POSITION accessor 0 holds a NaN or infinite value");
}

// Finite uvs past about 2e34 overflow the GPU's texture addressing (uv x texture side): the
// loader clamps them to kMaxUvMagnitude with one warning naming the accessor, or, under
// --strict, refuses the file naming the accessor and the value. A NaN in the same accessor
// is its own repair.
TEST_F(GltfGenerated, HugeFiniteUvsAreClampedLoudly) {
    float uvs[6] = {std::nanf(""), 0, 3.2e38f, 1, -1e35f, 0x1p112f};
    auto& attributes = gltf_["meshes"][0]["primitives"][0]["attributes"];
    const int accessor = addAccessor({{"bufferView", addView(uvs, sizeof uvs)},
                                      {"componentType", 5126},
                                      {"count", 3},
                                      {"type", "VEC2"}});
    attributes["TEXCOORD_0"] = accessor;
    fs::path path = write();
    Loaded l = load(path);
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    const Mesh& m = l.scene->meshes[0];
    EXPECT_EQ(m.uvs[0], glm::vec2(0.0f));
    EXPECT_EQ(m.uvs[1], glm::vec2(0x1p112f, 1.0f));
    EXPECT_EQ(m.uvs[2], glm::vec2(-0x1p112f, 0x1p112f)); // the limit kept
    ASSERT_EQ(l.scene->repairs.size(), 2u);
    EXPECT_EQ(l.scene->repairs[1].attribute, "TEXCOORD_0");
    EXPECT_EQ(l.scene->repairs[1].accessor, accessor);
    EXPECT_EQ(l.scene->repairs[1].count, 2u);
    const std::string named = "repaired TEXCOORD_0 accessor " + std::to_string(accessor) + ": ";
    EXPECT_TRUE(anyContains(l.warnings, named + "1 of 3 values were NaN or infinite"));
    EXPECT_TRUE(anyContains(l.warnings, named + "2 of 3 values were finite but past 5.1923e+33 "
                                                "(largest 3.2e+38)"));

    GltfLoadOptions strict;
    strict.strict = true;
    float finiteUvs[6] = {0, 0, 3.2e38f, 1, 0, 1};
    std::memcpy(bin_.data() + bin_.size() - sizeof finiteUvs, finiteUvs, sizeof finiteUvs);
    expectOneLineError(load(write(), strict), path,
                       "TEXCOORD_0 accessor " + std::to_string(accessor) +
                           " holds a uv of 3.2e+38, past the 5.1923e+33");
}

// A texture transform can take uvs past the limit too: clamped, with a warning naming the
// material.
TEST_F(GltfGenerated, TextureTransformPastTheUvLimitIsClamped) {
    float uvs[6] = {0, 0, 1e30f, 0, 0, 1};
    gltf_["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] =
        addAccessor({{"bufferView", addView(uvs, sizeof uvs)},
                     {"componentType", 5126},
                     {"count", 3},
                     {"type", "VEC2"}});
    gltf_["extensionsUsed"] = {"KHR_texture_transform"};
    gltf_["materials"] = {
        {{"pbrMetallicRoughness",
          {{"baseColorTexture",
            {{"index", 0},
             {"extensions", {{"KHR_texture_transform", {{"scale", {1e10, 1}}}}}}}}}}}};
    gltf_["meshes"][0]["primitives"][0]["material"] = 0;
    gltf_["textures"] = {{{"source", 0}}};
    gltf_["images"] = {{{"uri", "missing.png"}}};
    Loaded l = load(write());
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    EXPECT_EQ(l.scene->meshes[0].uvs[1], glm::vec2(0x1p112f, 0.0f));
    EXPECT_TRUE(anyContains(l.warnings, "material 0's KHR_texture_transform takes 1 uvs past "
                                        "5.1923e+33; clamped there"));
}

TEST(GltfImages, ToRgba8ConvertsChannelsAndDepths) {
    std::vector<uint8_t> out;
    const uint8_t grey[2] = {10, 20};
    ASSERT_TRUE(gltf::toRgba8(grey, 2, 2, 1, 1, 8, out));
    EXPECT_EQ(out, (std::vector<uint8_t>{10, 10, 10, 255, 20, 20, 20, 255}));
    const uint8_t greyAlpha[2] = {10, 99};
    ASSERT_TRUE(gltf::toRgba8(greyAlpha, 2, 1, 1, 2, 8, out));
    EXPECT_EQ(out, (std::vector<uint8_t>{10, 10, 10, 99}));
    const uint8_t rgb[3] = {1, 2, 3};
    ASSERT_TRUE(gltf::toRgba8(rgb, 3, 1, 1, 3, 8, out));
    EXPECT_EQ(out, (std::vector<uint8_t>{1, 2, 3, 255}));
    const uint16_t rgba16[4] = {0, 65535, 32896, 257}; // little endian, as stb returns them
    ASSERT_TRUE(gltf::toRgba8((const uint8_t*)rgba16, 8, 1, 1, 4, 16, out));
    EXPECT_EQ(out, (std::vector<uint8_t>{0, 255, 128, 1}));
    EXPECT_FALSE(gltf::toRgba8(rgb, 3, 2, 2, 3, 8, out)); // too few bytes
    EXPECT_FALSE(gltf::toRgba8(rgb, 3, 1, 1, 5, 8, out));
}

TEST(GltfImages, TangentsFromUvsFollowTheGltfConvention) {
    // A quad facing +z; u grows along +x, v grows along -y (glTF: v = 0 at the image top).
    std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    std::vector<glm::vec3> n(4, glm::vec3(0, 0, 1));
    std::vector<glm::vec2> uv = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    std::vector<uint32_t> idx = {0, 1, 2, 0, 2, 3};
    std::vector<glm::vec4> t;
    gltf::makeTangents(p, n, uv, idx, t);
    for (const glm::vec4& x : t)
        EXPECT_EQ(x, glm::vec4(1, 0, 0, 1)); // bitangent +y: image up
    for (glm::vec2& x : uv)
        x.x = 1.0f - x.x; // mirrored in u
    gltf::makeTangents(p, n, uv, idx, t);
    for (const glm::vec4& x : t)
        EXPECT_EQ(x, glm::vec4(-1, 0, 0, -1));
}

} // namespace
