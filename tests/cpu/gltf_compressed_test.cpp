// Compressed glTF (KHR_draco_mesh_compression, EXT_meshopt_compression), KHR_texture_transform
// and repaired attributes, on scenes the tests write (gltf_test_scenes.h) and on the shared
// Duck-Draco and TextureTransformTest; hostile compressed data (truncated, corrupt, lying
// counts) must give one line, no crash.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/scene/gltf_internal.h"
#include "core/scene/gltf_loader.h"
#include "gltf_test_scenes.h"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace tp;

namespace {

struct CompressedLoad {
    Result<Scene> scene;
    std::vector<std::string> warnings;
};

CompressedLoad loadCompressed(const fs::path& path, GltfLoadOptions options = {}) {
    std::vector<std::string> warnings;
    options.warnings = &warnings;
    Result<Scene> scene = loadGltf(path.string(), options);
    return {std::move(scene), std::move(warnings)};
}

fs::path freshDir(const std::string& name) {
    fs::path dir =
        fs::temp_directory_path() / ("triptych_gltfc_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(dir);
    return dir;
}

std::vector<char> readCompressedBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void expectOneLine(const CompressedLoad& l, const std::string& reason) {
    ASSERT_FALSE(l.scene.ok());
    EXPECT_EQ(l.scene.error().find('\n'), std::string::npos) << l.scene.error();
    EXPECT_NE(l.scene.error().find("scene.gltf: "), std::string::npos) << l.scene.error();
    EXPECT_NE(l.scene.error().find(reason), std::string::npos)
        << "expected '" << reason << "' in " << l.scene.error();
}

// Every vertex of `a` is within `tolerance` of a vertex of `b` (brute force: small meshes).
double farthest(const Scene& a, const Scene& b) {
    double worst = 0;
    for (const glm::vec3& p : a.meshes[0].positions) {
        double best = 1e30;
        for (const glm::vec3& q : b.meshes[0].positions)
            best = std::min(best, double(glm::length(p - q)));
        worst = std::max(worst, best);
    }
    return worst;
}

void expectUnitFiniteNormals(const Scene& s) {
    for (const Mesh& m : s.meshes)
        for (size_t i = 0; i < m.normals.size(); ++i) {
            ASSERT_NEAR(glm::length(m.normals[i]), 1.0f, 1e-4f) << i;
            ASSERT_NEAR(glm::length(glm::vec3(m.tangents[i])), 1.0f, 1e-4f) << i;
            ASSERT_TRUE(std::isfinite(m.uvs[i].x) && std::isfinite(m.uvs[i].y)) << i;
        }
}

class GltfCompressed : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = freshDir(::testing::UnitTest::GetInstance()->current_test_info()->name());
        plain_ = loadCompressed(test::writePlainScene(dir_ / "plain"));
        ASSERT_TRUE(plain_.scene.ok()) << plain_.scene.error();
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
    CompressedLoad plain_{Error{"not loaded"}, {}};
};

TEST_F(GltfCompressed, DracoSceneDecodesToThePlainMesh) {
    CompressedLoad l = loadCompressed(test::writeDracoScene(dir_ / "draco"));
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
    const Scene& s = *l.scene;
    EXPECT_EQ(s.triangleCount(), plain_.scene->triangleCount());
    EXPECT_EQ(s.extensions, std::vector<std::string>{"KHR_draco_mesh_compression (libdraco)"});
    // 16-bit positions over a 6 m box: within a millimetre.
    EXPECT_LT(farthest(s, *plain_.scene), 1e-3);
    EXPECT_LT(farthest(*plain_.scene, s), 1e-3);
    expectUnitFiniteNormals(s);
    EXPECT_NEAR(s.bounds.max.y, 2.0f, 1e-3f);
}

TEST_F(GltfCompressed, MeshoptSceneDecodesExactly) {
    CompressedLoad l = loadCompressed(test::writeMeshoptScene(dir_ / "meshopt"));
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
    const Scene& s = *l.scene;
    EXPECT_EQ(s.extensions, std::vector<std::string>{"EXT_meshopt_compression (meshoptimizer)"});
    const Mesh& a = s.meshes[0];
    const Mesh& b = plain_.scene->meshes[0];
    ASSERT_EQ(a.positions.size(), b.positions.size());
    EXPECT_EQ(a.positions, b.positions); // the vertex codec is lossless
    EXPECT_EQ(a.uvs, b.uvs);
    size_t far = 0; // 8-bit octahedral normals: within a few degrees
    for (size_t i = 0; i < a.normals.size(); ++i)
        far += glm::dot(a.normals[i], b.normals[i]) < 0.995f;
    EXPECT_EQ(far, 0u);
    // The index codec keeps the triangles and their winding, possibly rotated.
    ASSERT_EQ(a.indices.size(), b.indices.size());
    std::multiset<std::array<uint32_t, 3>> ta, tb;
    auto canonical = [](uint32_t x, uint32_t y, uint32_t z) {
        // rotate so the smallest comes first (keeps the winding)
        if (y < x && y < z) return std::array<uint32_t, 3>{y, z, x};
        if (z < x && z < y) return std::array<uint32_t, 3>{z, x, y};
        return std::array<uint32_t, 3>{x, y, z};
    };
    for (size_t t = 0; t < a.indices.size(); t += 3) {
        ta.insert(canonical(a.indices[t], a.indices[t + 1], a.indices[t + 2]));
        tb.insert(canonical(b.indices[t], b.indices[t + 1], b.indices[t + 2]));
    }
    EXPECT_TRUE(ta == tb);
}

// The .gltf as a .glb: buffer 0 becomes the BIN chunk (the meshopt fallback buffer keeps no uri).
fs::path toGlb(const fs::path& gltfPath) {
    json j = json::parse(std::ifstream(gltfPath));
    std::vector<char> bin =
        readCompressedBytes(gltfPath.parent_path() / j["buffers"][0]["uri"].get<std::string>());
    j["buffers"][0].erase("uri");
    std::string text = j.dump();
    while (text.size() % 4)
        text.push_back(' ');
    while (bin.size() % 4)
        bin.push_back(0);
    std::vector<char> glb;
    auto u32 = [&](uint32_t v) {
        for (int i = 0; i < 4; ++i)
            glb.push_back(char(v >> (8 * i)));
    };
    u32(0x46546C67u);
    u32(2);
    u32(uint32_t(12 + 8 + text.size() + 8 + bin.size()));
    u32(uint32_t(text.size()));
    u32(0x4E4F534Au);
    glb.insert(glb.end(), text.begin(), text.end());
    u32(uint32_t(bin.size()));
    u32(0x004E4942u);
    glb.insert(glb.end(), bin.begin(), bin.end());
    const fs::path out = gltfPath.parent_path() / "scene.glb";
    std::ofstream(out, std::ios::binary).write(glb.data(), std::streamsize(glb.size()));
    return out;
}

TEST_F(GltfCompressed, CompressedGlbFilesLoadAsTheirGltf) {
    for (const fs::path& gltf :
         {test::writeMeshoptScene(dir_ / "meshopt"), test::writeDracoScene(dir_ / "draco")}) {
        SCOPED_TRACE(gltf.string());
        CompressedLoad a = loadCompressed(gltf), b = loadCompressed(toGlb(gltf));
        ASSERT_TRUE(a.scene.ok()) << a.scene.error();
        ASSERT_TRUE(b.scene.ok()) << b.scene.error();
        EXPECT_EQ(a.scene->extensions, b.scene->extensions);
        EXPECT_EQ(a.scene->meshes[0].positions, b.scene->meshes[0].positions);
        EXPECT_EQ(a.scene->meshes[0].indices, b.scene->meshes[0].indices);
    }
}

TEST_F(GltfCompressed, RepairSceneIsRepairedAndListed) {
    test::RepairCounts counts;
    const fs::path path = test::writeRepairScene(dir_ / "repair", counts);
    CompressedLoad l = loadCompressed(path);
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    const Scene& s = *l.scene;
    expectUnitFiniteNormals(s);
    std::map<std::string, size_t> repaired;
    for (const SceneRepair& r : s.repairs)
        repaired[r.attribute] = r.count;
    EXPECT_EQ(repaired["NORMAL"], counts.nanNormals + counts.zeroNormals);
    EXPECT_EQ(repaired["TANGENT"], counts.badTangents);
    EXPECT_EQ(repaired["TEXCOORD_0"], counts.badUvs);
    EXPECT_EQ(s.repairs.size(), 3u);
    EXPECT_EQ(l.warnings.size(), 3u);
    // Repaired sphere normals point away from the centre, as the true ones do.
    const Mesh& m = s.meshes[0];
    for (size_t i = 0; i + 4 < m.positions.size(); ++i)
        ASSERT_GT(glm::dot(m.normals[i], glm::normalize(m.positions[i] - glm::vec3(0, 1, 0))), 0.9f)
            << i;
    GltfLoadOptions strict;
    strict.strict = true;
    CompressedLoad refused = loadCompressed(path, strict);
    ASSERT_FALSE(refused.scene.ok());
    EXPECT_NE(refused.scene.error().find("NORMAL accessor"), std::string::npos)
        << refused.scene.error();
}

TEST_F(GltfCompressed, TextureTransformIsBakedIntoTheUvs) {
    CompressedLoad l = loadCompressed(test::writeTextureTransformScene(dir_ / "transform"));
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
    EXPECT_EQ(l.scene->extensions, std::vector<std::string>{"KHR_texture_transform"});
    const Mesh& a = l.scene->meshes[0];
    const Mesh& b = plain_.scene->meshes[0];
    for (size_t i = 0; i < a.uvs.size(); ++i) {
        // offset (0.5, 0), rotation pi/2, scale (2, 1): u' = 0.5 + v, v' = -2u.
        const glm::vec2 expected(0.5f + b.uvs[i].y, -2.0f * b.uvs[i].x);
        ASSERT_NEAR(glm::length(a.uvs[i] - expected), 0.0f, 1e-5f) << i;
    }
}

TEST_F(GltfCompressed, TextureTransformThatIsNotAnObjectIsIgnored) {
    fs::path path = test::writeTextureTransformScene(dir_ / "notobject");
    json j = json::parse(std::ifstream(path));
    j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]
     ["KHR_texture_transform"] = 7;
    std::ofstream(path) << j.dump();
    CompressedLoad l = loadCompressed(path);
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    EXPECT_EQ(l.scene->meshes[0].uvs, plain_.scene->meshes[0].uvs);
}

TEST_F(GltfCompressed, TextureTransformsThatDifferWarn) {
    fs::path path = test::writeTextureTransformScene(dir_ / "differ");
    json j = json::parse(std::ifstream(path));
    j["materials"][0]["normalTexture"] = {{"index", 0}};
    j["materials"][0]["emissiveTexture"] = {
        {"index", 0},
        {"extensions", {{"KHR_texture_transform", {{"offset", {0, 0}}, {"texCoord", 1}}}}}};
    std::ofstream(path) << j.dump();
    CompressedLoad l = loadCompressed(path);
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    ASSERT_EQ(l.warnings.size(), 1u);
    EXPECT_NE(l.warnings[0].find("differs between baseColorTexture and normalTexture"),
              std::string::npos)
        << l.warnings[0];
}

// Truncated, corrupt and lying compressed data: one line naming the extension, never a crash.
TEST_F(GltfCompressed, HostileDracoData) {
    const fs::path path = test::writeDracoScene(dir_ / "draco");
    const fs::path bin = path.parent_path() / "scene.bin";
    const std::vector<char> good = readCompressedBytes(bin);
    json j = json::parse(std::ifstream(path));
    const size_t length = j["bufferViews"][0]["byteLength"];
    auto withView = [&](size_t newLength, auto&& corrupt) {
        std::vector<char> bytes = good;
        corrupt(bytes);
        std::ofstream(bin, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
        json k = j;
        k["bufferViews"][0]["byteLength"] = newLength;
        std::ofstream(path) << k.dump();
        return loadCompressed(path);
    };
    for (size_t cut : {size_t(0), size_t(1), size_t(8), length / 3, length / 2, length - 1}) {
        SCOPED_TRACE(cut);
        CompressedLoad l = withView(cut, [](std::vector<char>&) {});
        expectOneLine(l, "KHR_draco_mesh_compression");
    }
    for (size_t seed = 1; seed <= 40; ++seed) {
        SCOPED_TRACE(seed);
        CompressedLoad l = withView(length, [&](std::vector<char>& b) {
            for (size_t k = 0; k < 4; ++k)
                b[(seed * 7919 + k * 104729) % length] ^= char(0x5a + seed + k);
        });
        if (!l.scene.ok()) {
            EXPECT_EQ(l.scene.error().find('\n'), std::string::npos);
        } else {
            expectUnitFiniteNormals(*l.scene); // decoded something else: still usable
        }
    }
    // Counts that disagree with the bitstream.
    json k = j;
    k["accessors"][0]["count"] = 7;
    std::ofstream(bin, std::ios::binary).write(good.data(), std::streamsize(good.size()));
    std::ofstream(path) << k.dump();
    expectOneLine(loadCompressed(path), "POSITION accessor declares 7");
}

TEST_F(GltfCompressed, HostileMeshoptData) {
    const fs::path path = test::writeMeshoptScene(dir_ / "meshopt");
    json j = json::parse(std::ifstream(path));
    auto with = [&](auto&& change) {
        json k = j;
        change(k["bufferViews"][0]["extensions"]["EXT_meshopt_compression"], k);
        std::ofstream(path) << k.dump();
        return loadCompressed(path);
    };
    const size_t length =
        j["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["byteLength"];
    for (size_t cut : {size_t(0), size_t(1), length / 2, length - 1}) {
        SCOPED_TRACE(cut);
        expectOneLine(with([&](json& e, json&) { e["byteLength"] = cut; }),
                      "EXT_meshopt_compression");
    }
    expectOneLine(with([](json& e, json&) { e["mode"] = "SPARKLES"; }), "unknown mode");
    // A fallback flag that is not true: the buffer keeps no uri, which a .gltf cannot have.
    expectOneLine(with([](json&, json& k) {
                      k["buffers"][1]["extensions"]["EXT_meshopt_compression"]["fallback"] = "yes";
                  }),
                  "buffer 1 has no uri");
    expectOneLine(with([](json& e, json&) { e["filter"] = "QUATERNION"; }), "filter QUATERNION");
    expectOneLine(with([](json& e, json&) { e["byteStride"] = 6; }), "byteLength");
    expectOneLine(with([](json& e, json&) { e["buffer"] = 9; }), "buffer 9 does not exist");
    expectOneLine(with([](json& e, json&) { e["byteOffset"] = 1u << 30; }), "lie outside");
    // A count no compressed data of this size can hold: refused before allocating.
    expectOneLine(with([](json& e, json& k) {
                      e["count"] = 1u << 26;
                      k["bufferViews"][0]["byteLength"] = (1ull << 26) * 12;
                  }),
                  "cannot hold");
    // Garbage in the middle of the stream.
    const fs::path bin = path.parent_path() / "scene.bin";
    std::vector<char> bytes = readCompressedBytes(bin);
    const size_t offset =
        j["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["byteOffset"];
    for (size_t k = 0; k < length; k += 3)
        bytes[offset + k] = char(0xff);
    std::ofstream(bin, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    CompressedLoad l = loadCompressed(path);
    if (!l.scene.ok()) {
        EXPECT_EQ(l.scene.error().find('\n'), std::string::npos);
    }
}

// ---- Shared scenes, when present ------------------------------------------------------------

fs::path sharedScenes() {
    return fs::path(TP_SHARED_SCENES);
}

TEST(GltfSharedCompressed, DuckDraco) {
    const fs::path path = sharedScenes() / "Duck-Draco/glTF-Draco/Duck.gltf";
    if (!fs::exists(path)) GTEST_SKIP() << path << " not found; skipping";
    CompressedLoad l = loadCompressed(path);
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    EXPECT_EQ(l.scene->triangleCount(), 4212u);
    EXPECT_EQ(l.scene->extensions,
              std::vector<std::string>{"KHR_draco_mesh_compression (libdraco)"});
    EXPECT_EQ(l.scene->textures.size(), 1u);
    expectUnitFiniteNormals(*l.scene);
    for (const std::string& w : l.warnings)
        ADD_FAILURE() << w;
}

TEST(GltfSharedCompressed, TextureTransformTest) {
    const fs::path path = sharedScenes() / "TextureTransformTest/glTF/TextureTransformTest.gltf";
    if (!fs::exists(path)) GTEST_SKIP() << path << " not found; skipping";
    CompressedLoad l = loadCompressed(path);
    ASSERT_TRUE(l.scene.ok()) << l.scene.error();
    EXPECT_EQ(l.scene->triangleCount(), 24u);
    EXPECT_NE(
        std::find(l.scene->extensions.begin(), l.scene->extensions.end(), "KHR_texture_transform"),
        l.scene->extensions.end());
    for (const std::string& w : l.warnings)
        EXPECT_EQ(w.find("KHR_texture_transform"), std::string::npos) << w;
}

} // namespace
