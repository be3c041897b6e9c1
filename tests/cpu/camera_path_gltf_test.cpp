// A glTF file's animated camera as a camera path (core/camera/camera_path.h, form b): a tiny
// .gltf with its buffer in a data: URI, a camera node under a translated parent, sampled at
// the keyframes, between them (LINEAR, STEP, CUBICSPLINE) and with the animation on the
// parent instead of the camera's node.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>

#include <nlohmann/json.hpp>

#include "compare/report/report_html.h"
#include "core/camera/camera_path.h"
#include "temp_path.h"
#include "tests/cli/hostile_scenes.h"

using namespace tp;
using nlohmann::json;

namespace {

namespace fs = std::filesystem;

struct AnimatedCameraFile {
    std::string rotation = "LINEAR"; // the rotation sampler's interpolation
    bool onParent = false;           // the translation channel targets the parent node
    bool cubic = false;              // the translation sampler is CUBICSPLINE
    bool animated = true;
    std::function<void(json&)> spoil; // breaks the glTF before it is written
};

// Keyframes at t = 0, 1, 2: translations (0,0,5), (2,0,5), (2,0,1); rotations about +y by 0,
// 90 and 180 degrees. The camera (node 1, yfov 0.9, znear 0.1, no zfar) sits under node 0,
// translated by (0, 1, 0); with onParent, node 0 is the one translated by the animation and
// the camera sits at (0, 0, 1) under it.
fs::path writeAnimatedCamera(const std::string& name, const AnimatedCameraFile& f) {
    const float s = std::sqrt(0.5f);
    const std::vector<float> data = {
        0, 1, 2,                                      // times
        0, 0, 5, 2,      0, 5, 2,      0, 1,          // translations
        0, 0, 0, 1,      0, s, 0,      s, 0, 1, 0, 0, // rotations (xyzw)
        0, 0, 0, /**/ 0, 0, 5, /**/ 4, 0, 0,          // cubic key 0: in, value, out
        0, 0, 0, /**/ 2, 0, 5, /**/ 0, 0, 0,          // key 1
        0, 0, 0, /**/ 2, 0, 1, /**/ 0, 0, 0};         // key 2
    std::string bytes(data.size() * 4, '\0');
    std::memcpy(bytes.data(), data.data(), bytes.size());
    auto accessor = [](size_t offset, size_t count, const char* type) {
        return json{{"bufferView", 0},
                    {"byteOffset", offset * 4},
                    {"componentType", 5126},
                    {"count", count},
                    {"type", type}};
    };
    json input = accessor(0, 3, "SCALAR");
    input["min"] = {0};
    input["max"] = {2};
    json g = {
        {"asset", {{"version", "2.0"}}},
        {"buffers",
         {{{"byteLength", bytes.size()},
           {"uri", "data:application/octet-stream;base64," + cli::base64(bytes)}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteLength", bytes.size()}}}},
        {"accessors",
         {input, accessor(3, 3, "VEC3"), accessor(12, 3, "VEC4"), accessor(24, 9, "VEC3")}},
        {"cameras", {{{"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.1}}}}}},
        {"nodes",
         {{{"children", {1}}, {"translation", {0, 1, 0}}},
          {{"camera", 0}, {"translation", {0, 0, 1}}}}},
        {"scenes", {{{"nodes", {0}}}}},
        {"scene", 0}};
    if (f.animated)
        g["animations"] = {{{"samplers",
                             {{{"input", 0},
                               {"output", f.cubic ? 3 : 1},
                               {"interpolation", f.cubic ? "CUBICSPLINE" : "LINEAR"}},
                              {{"input", 0}, {"output", 2}, {"interpolation", f.rotation}}}},
                            {"channels",
                             {{{"sampler", 0},
                               {"target", {{"node", f.onParent ? 0 : 1}, {"path", "translation"}}}},
                              {{"sampler", 1}, {"target", {{"node", 1}, {"path", "rotation"}}}}}}}};
    if (f.spoil) f.spoil(g);
    const fs::path dir = testTempPath("animated_camera"); // the name must end in .gltf
    fs::create_directories(dir);
    const fs::path path = dir / (name + ".gltf");
    std::ofstream(path) << g.dump();
    return path;
}

void expectNearVec(glm::vec3 got, glm::vec3 want, const std::string& what) {
    EXPECT_NEAR(got.x, want.x, 1e-5f) << what;
    EXPECT_NEAR(got.y, want.y, 1e-5f) << what;
    EXPECT_NEAR(got.z, want.z, 1e-5f) << what;
}

const glm::vec3 kKeyTranslations[3] = {{0, 0, 5}, {2, 0, 5}, {2, 0, 1}};
const glm::vec3 kKeyForwards[3] = {{0, 0, -1}, {-1, 0, 0}, {0, 0, 1}}; // -z turned about +y

} // namespace

TEST(CameraPathGltf, KeyframesGiveTheKeyframePoses) {
    const fs::path path = writeAnimatedCamera("keys", {});
    Result<std::vector<Camera>> views = readCameraPath(path.string(), 5);
    ASSERT_TRUE(views.ok()) << views.error();
    ASSERT_EQ(views->size(), 5u);
    for (size_t k = 0; k < 3; ++k) {
        const Camera& c = (*views)[2 * k];
        const std::string what = "keyframe " + std::to_string(k);
        expectNearVec(c.position, kKeyTranslations[k] + glm::vec3(0, 1, 0), what);
        expectNearVec(c.target - c.position, kKeyForwards[k], what);
        expectNearVec(c.up, {0, 1, 0}, what);
        EXPECT_EQ(c.yfov, 0.9f);
        EXPECT_EQ(c.znear, 0.1f);
        EXPECT_EQ(c.zfar, 0.0f);
    }
    // Half way to keyframe 1 (t = 0.5): translation linear, rotation slerped to 45 degrees.
    expectNearVec((*views)[1].position, {1, 1, 5}, "t 0.5");
    expectNearVec((*views)[1].target - (*views)[1].position,
                  {-std::sqrt(0.5f), 0, -std::sqrt(0.5f)}, "t 0.5");
    fs::remove(path);
}

TEST(CameraPathGltf, StepAndCubicSamplers) {
    AnimatedCameraFile f;
    f.rotation = "STEP";
    f.cubic = true;
    const fs::path path = writeAnimatedCamera("step_cubic", f);
    Result<std::vector<Camera>> views = readCameraPath(path.string(), 5);
    ASSERT_TRUE(views.ok()) << views.error();
    for (size_t k = 0; k < 3; ++k)
        expectNearVec((*views)[2 * k].position, kKeyTranslations[k] + glm::vec3(0, 1, 0),
                      "keyframe " + std::to_string(k));
    // STEP holds keyframe 0's rotation until t = 1.
    expectNearVec((*views)[1].target - (*views)[1].position, kKeyForwards[0], "step");
    // Hermite at s = 1/2 with out-tangent (4,0,0) at keyframe 0, zero in-tangent at 1 and a
    // one-second interval: x = (0 + 2) / 2 + 4 / 8.
    expectNearVec((*views)[1].position, {1.5f, 1, 5}, "cubic");
    fs::remove(path);
}

TEST(CameraPathGltf, AnimatedAncestorMovesTheCamera) {
    AnimatedCameraFile f;
    f.onParent = true;
    const fs::path path = writeAnimatedCamera("parent", f);
    Result<std::vector<Camera>> views = readCameraPath(path.string(), 3);
    ASSERT_TRUE(views.ok()) << views.error();
    for (size_t k = 0; k < 3; ++k)
        expectNearVec((*views)[k].position, kKeyTranslations[k] + glm::vec3(0, 0, 1),
                      "keyframe " + std::to_string(k));
    fs::remove(path);
}

TEST(CameraPathGltf, RefusesAFileWithoutAnAnimatedCamera) {
    AnimatedCameraFile f;
    f.animated = false;
    const fs::path path = writeAnimatedCamera("still", f);
    Result<std::vector<Camera>> views = readCameraPath(path.string(), 5);
    ASSERT_FALSE(views.ok());
    EXPECT_EQ(views.error(),
              path.string() + ": no node of the default scene has a perspective camera whose "
                              "translation or rotation is animated (on the node or an ancestor)");
    views = readCameraPath(writeAnimatedCamera("zero", {}).string(), 0);
    ASSERT_FALSE(views.ok());
    EXPECT_NE(views.error().find("frames must be from 1 to 100000 (got 0)"), std::string::npos)
        << views.error();
    fs::remove_all(testTempPath("animated_camera"));
}

// Broken animations, and every hostile scene of the loader's tests (none has an animated
// camera): one line naming the file, never a crash.
TEST(CameraPathGltf, HostileFilesFailWithOneLine) {
    const std::vector<std::pair<std::function<void(json&)>, std::string>> spoils = {
        {[](json& g) { g["animations"][0]["samplers"][0]["input"] = 9; },
         "accessor 9 does not exist (the file has 4)"},
        {[](json& g) { g["animations"][0]["channels"][0]["sampler"] = 5; },
         "animation 0: sampler 5 does not exist"},
        {[](json& g) { g["animations"][0]["samplers"][1]["interpolation"] = "SMOOTH"; },
         "animation 0 sampler 1: unknown interpolation \"SMOOTH\""},
        {[](json& g) { g["animations"][0]["samplers"][1]["output"] = 1; },
         "animation output accessor 1 is VEC3, which animation output cannot be"},
        {[](json& g) { g["accessors"][1]["count"] = 2; },
         "animation 0 sampler 0: 2 output values for 3 keyframes"},
        {[](json& g) {
             g["nodes"][1]["matrix"] =
                 json::array({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
         },
         "node 1 has a matrix, which an animation cannot target"},
        {[](json& g) { g["cameras"][0]["perspective"]["yfov"] = 4.0; }, "view 0: \"yfov_degrees\""},
    };
    for (size_t i = 0; i < spoils.size(); ++i) {
        AnimatedCameraFile f;
        f.spoil = spoils[i].first;
        const fs::path path = writeAnimatedCamera("spoilt" + std::to_string(i), f);
        Result<std::vector<Camera>> views = readCameraPath(path.string(), 5);
        ASSERT_FALSE(views.ok()) << i;
        EXPECT_EQ(views.error().rfind(path.string() + ": ", 0), 0u) << views.error();
        EXPECT_NE(views.error().find(spoils[i].second), std::string::npos) << views.error();
        EXPECT_EQ(views.error().find('\n'), std::string::npos) << views.error();
    }
    const fs::path root = testTempPath("camera_path_hostile");
    for (const hostile::Case& c : hostile::writeHostileScenes(root)) {
        const std::string scene = (root / c.name / c.scene).string();
        Result<std::vector<Camera>> views = readCameraPath(scene, 5);
        ASSERT_FALSE(views.ok()) << c.name;
        EXPECT_EQ(views.error().find('\n'), std::string::npos) << views.error();
    }
    fs::remove_all(root);
    fs::remove_all(testTempPath("animated_camera"));
}
