// Where a run's camera comes from (core/cli/scene_input.h, CameraSource): the glTF loader names
// the file's camera it used, and loadScene records a built-in scene's own camera, a glTF's
// camera (by index) or framing, and --camera's file, which replaces any of them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "compare/report/report_html.h"
#include "core/camera/camera_file.h"
#include "core/cli/scene_input.h"
#include "core/scene/gltf_loader.h"
#include "temp_path.h"

using namespace tp;
using nlohmann::json;

namespace {

namespace fs = std::filesystem;

// One triangle (its buffer a data: URI), and `cameras` on nodes after the mesh's node.
fs::path writeTriangle(const std::string& name, const json& cameras, const json& cameraNodes) {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::string bytes(reinterpret_cast<const char*>(positions), sizeof positions);
    json g = {{"asset", {{"version", "2.0"}}},
              {"buffers",
               {{{"byteLength", 36},
                 {"uri", "data:application/octet-stream;base64," + cli::base64(bytes)}}}},
              {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
              {"accessors",
               {{{"bufferView", 0},
                 {"componentType", 5126},
                 {"count", 3},
                 {"type", "VEC3"},
                 {"min", {0, 0, 0}},
                 {"max", {1, 1, 0}}}}},
              {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
              {"nodes", {{{"mesh", 0}}}},
              {"scenes", {{{"nodes", {0}}}}}};
    if (!cameras.empty()) g["cameras"] = cameras;
    for (const json& node : cameraNodes) {
        g["nodes"].push_back(node);
        g["scenes"][0]["nodes"].push_back(g["nodes"].size() - 1);
    }
    const fs::path path = testTempPath("camera_source_" + name + ".gltf");
    std::ofstream(path) << g.dump();
    return path;
}

json twoCameras() { // the loader takes perspective cameras only: index 1 is the one
    return json::parse(
        R"([{"type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 10}},
                            {"type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.01}}])");
}

} // namespace

TEST(CameraSource, GltfLoaderNamesTheCameraItUsed) {
    const fs::path withCamera = writeTriangle("with", twoCameras(), json::parse(R"([
        {"translation": [0, 0, 5], "camera": 0}, {"translation": [0.5, 0.5, 3], "camera": 1}])"));
    int index = -7;
    GltfLoadOptions options;
    options.cameraIndex = &index;
    Result<Scene> s = loadGltf(withCamera.string(), options);
    ASSERT_TRUE(s.ok()) << s.error();
    EXPECT_EQ(index, 1);
    EXPECT_EQ(s->camera.position, glm::vec3(0.5f, 0.5f, 3.0f));

    const fs::path without = writeTriangle("without", json::array(), json::array());
    s = loadGltf(without.string(), options);
    ASSERT_TRUE(s.ok()) << s.error();
    EXPECT_EQ(index, -1); // framed from the bounds
    fs::remove(withCamera);
    fs::remove(without);
}

TEST(CameraSource, LoadSceneRecordsWhereTheCameraCameFrom) {
    cli::SceneOptions o;
    o.lightCount = 0;
    cli::CameraSource source;
    o.scene = "builtin:courtyard-small";
    const Camera builtin = cli::loadScene(o, &source).camera;
    EXPECT_EQ(source.kind, "scene");

    o.scene = writeTriangle("gltf", twoCameras(),
                            json::parse(R"([{"translation": [0, 0, 3], "camera": 1}])"))
                  .string();
    cli::loadScene(o, &source);
    EXPECT_EQ(source.kind, "gltf");
    EXPECT_EQ(source.gltfCamera, 1);
    const std::string gltf = o.scene;

    o.scene = writeTriangle("framed", json::array(), json::array()).string();
    cli::loadScene(o, &source);
    EXPECT_EQ(source.kind, "framed");
    const std::string framed = o.scene;

    // --camera replaces a glTF's camera and a built-in one alike.
    Camera view = builtin;
    view.position = {2.0f, 3.0f, 4.0f};
    view.zfar = 500.0f;
    o.cameraFile = testTempPath("camera_source_view.json").string();
    ASSERT_TRUE(writeCameraFile(o.cameraFile, view).ok());
    for (const std::string& scene : {std::string("builtin:courtyard-small"), gltf}) {
        o.scene = scene;
        const Camera used = cli::loadScene(o, &source).camera;
        EXPECT_EQ(source.kind, "file") << scene;
        EXPECT_EQ(source.path, o.cameraFile);
        EXPECT_EQ(cameraToJson(used), cameraToJson(view)) << scene;
    }
    std::ofstream(o.cameraFile) << R"({"schema":"triptych.camera/1"})";
    EXPECT_THROW(cli::loadScene(o, &source), cli::UsageError);
    for (const std::string& f : {gltf, framed, o.cameraFile})
        fs::remove(f);
}
