// The hashes report.json carries to identify a scene (compare/cache/scene_hash.h): a built-in scene
// hashes the same every time it is generated and differently after any change to its data; a
// glTF's file hash covers the file and every buffer and image it references, and nothing else.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <cmath>

#include "compare/cache/scene_hash.h"
#include "core/camera/camera_file.h"
#include "core/scene/procedural.h"

using namespace tp;

namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

// A minimal .gltf with one external buffer, one external image, one data: URI image, and an
// unreferenced file next to them.
fs::path makeGltfFolder(const std::string& name) {
    fs::path dir = fs::temp_directory_path() /
                   ("triptych_scene_hash_" + name + "_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "tex");
    writeFile(dir / "scene.gltf", R"({"asset":{"version":"2.0"},
        "buffers":[{"uri":"geo%20data.bin","byteLength":4}],
        "images":[{"uri":"tex/albedo.png"},{"uri":"data:image/png;base64,AAAA"}]})");
    writeFile(dir / "geo data.bin", "abcd");
    writeFile(dir / "tex/albedo.png", "not really a png");
    writeFile(dir / "unrelated.txt", "x");
    return dir;
}

} // namespace

TEST(SceneHash, BuiltinContentIsStableAndSeesEveryChange) {
    Scene a = makeBuiltinScene("courtyard-small").value();
    Scene b = makeBuiltinScene("courtyard-small").value();
    const std::string hash = cli::hashSceneContent(a);
    EXPECT_EQ(hash.size(), 16u);
    EXPECT_EQ(hash, cli::hashSceneContent(b)); // generated again: same data, same hash
    EXPECT_NE(hash, cli::hashSceneContent(makeBuiltinScene("courtyard").value()));

    b.meshes.back().positions.back().y += 1e-3f; // one vertex
    EXPECT_NE(hash, cli::hashSceneContent(b));
    b = a;
    b.materials.front().roughnessFactor *= 0.5f;
    EXPECT_NE(hash, cli::hashSceneContent(b));
    b = a;
    ASSERT_FALSE(b.textures.empty());
    b.textures.back().rgba8.back() ^= 1; // one texel bit
    EXPECT_NE(hash, cli::hashSceneContent(b));
    b = a;
    b.camera.yfov += 0.01f;
    EXPECT_NE(hash, cli::hashSceneContent(b));
    b = a;
    b.lights.push_back(Light{}); // lights have their own hash
    EXPECT_EQ(hash, cli::hashSceneContent(b));
    EXPECT_NE(cli::hashLights(a.lights), cli::hashLights(b.lights));
    b.lights.back().intensity = 2.0f;
    EXPECT_NE(cli::hashLights(std::vector<Light>{Light{}}), cli::hashLights({b.lights.back()}));
}

TEST(SceneHash, FileHashCoversTheFileAndWhatItReferences) {
    fs::path dir = makeGltfFolder("files");
    const std::string gltf = (dir / "scene.gltf").string();
    cli::FileHashes h = cli::hashSceneFiles(gltf);
    ASSERT_EQ(h.files.size(), 3u); // the data: URI is in the file's bytes already
    EXPECT_EQ(fs::path(h.files[1]).filename(), "geo data.bin");
    EXPECT_EQ(fs::path(h.files[2]).filename(), "albedo.png");
    EXPECT_TRUE(h.missing.empty());
    EXPECT_EQ(h.hash.size(), 16u);

    writeFile(dir / "unrelated.txt", "y"); // not referenced: no change
    EXPECT_EQ(cli::hashSceneFiles(gltf).hash, h.hash);
    writeFile(dir / "geo data.bin", "abce"); // one byte of the buffer
    EXPECT_NE(cli::hashSceneFiles(gltf).hash, h.hash);
    writeFile(dir / "geo data.bin", "abcd");
    EXPECT_EQ(cli::hashSceneFiles(gltf).hash, h.hash);
    writeFile(dir / "tex/albedo.png", "not really a PNG"); // one byte of the image
    EXPECT_NE(cli::hashSceneFiles(gltf).hash, h.hash);
    writeFile(dir / "tex/albedo.png", "not really a png");

    // The same files in another folder: the same hash (names are hashed relative to the scene).
    fs::path copy = dir.string() + "_copy";
    fs::remove_all(copy);
    fs::copy(dir, copy, fs::copy_options::recursive);
    EXPECT_EQ(cli::hashSceneFiles((copy / "scene.gltf").string()).hash, h.hash);

    fs::remove(dir / "tex/albedo.png"); // a missing reference is listed and changes the hash
    cli::FileHashes missing = cli::hashSceneFiles(gltf);
    ASSERT_EQ(missing.missing.size(), 1u);
    EXPECT_EQ(fs::path(missing.missing[0]).filename(), "albedo.png");
    EXPECT_NE(missing.hash, h.hash);
    EXPECT_TRUE(cli::hashSceneFiles((dir / "nope.gltf").string()).hash.empty());
    fs::remove_all(dir);
    fs::remove_all(copy);
}

TEST(SceneHash, GlbHashesItsJsonReferences) {
    fs::path dir = makeGltfFolder("glb");
    std::string json = R"({"asset":{"version":"2.0"},"images":[{"uri":"tex/albedo.png"}]})";
    while (json.size() % 4)
        json += ' ';
    std::string glb = "glTF";
    auto le32 = [&](uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
    le32(2);
    le32(uint32_t(12 + 8 + json.size()));
    le32(uint32_t(json.size()));
    le32(0x4E4F534Au); // "JSON"
    glb += json;
    writeFile(dir / "scene.glb", glb);
    cli::FileHashes h = cli::hashSceneFiles((dir / "scene.glb").string());
    ASSERT_EQ(h.files.size(), 2u);
    EXPECT_EQ(fs::path(h.files[1]).filename(), "albedo.png");
    fs::remove_all(dir);
}

// The camera's own hash (report.json camera_hash_fnv1a64): every field counts, a camera file's
// round trip keeps it, and the content hash follows the camera a run used (--camera).
TEST(SceneHash, CameraHashSeesEveryFieldAndSurvivesACameraFile) {
    Scene scene = makeBuiltinScene("courtyard-small").value();
    const Camera c = scene.camera;
    const std::string hash = cli::hashCamera(c);
    EXPECT_EQ(hash.size(), 16u);
    for (int field = 0; field < 12; ++field) {
        Camera d = c;
        float* values[] = {&d.position.x, &d.position.y, &d.position.z, &d.target.x,
                           &d.target.y,   &d.target.z,   &d.up.x,       &d.up.y,
                           &d.up.z,       &d.yfov,       &d.znear,      &d.zfar};
        *values[field] = std::nextafter(*values[field], 1e9f); // one ulp
        EXPECT_NE(cli::hashCamera(d), hash) << "field " << field;
        Scene moved = scene;
        moved.camera = d;
        EXPECT_NE(cli::hashSceneContent(moved), cli::hashSceneContent(scene)) << "field " << field;
    }
    const std::string path =
        (fs::temp_directory_path() / ("triptych_camera_hash_" + std::to_string(getpid()))).string();
    ASSERT_TRUE(writeCameraFile(path, c).ok());
    Result<Camera> back = readCameraFile(path);
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_EQ(cli::hashCamera(*back), hash);
    fs::remove(path);
}
