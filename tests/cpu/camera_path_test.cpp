// Camera paths (core/camera/camera_path.h): views at key times are the keys bit for bit, views
// are evenly spaced in time, the centripetal curve does not run backwards where keys are
// unevenly spaced, strict parsing with one-line errors, and a glTF file's animated camera
// sampled at its keyframes gives the keyframe poses.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "compare/report/report_html.h"
#include "core/camera/camera_file.h"
#include "core/camera/camera_path.h"
#include "temp_path.h"

using namespace tp;
using nlohmann::json;

namespace {

namespace fs = std::filesystem;

Camera pathKey(glm::vec3 position, glm::vec3 target, float yfov = 1.0f, float zfar = 0.0f) {
    Camera c;
    c.position = position;
    c.target = target;
    c.up = {0.0f, 1.0f, 0.0f};
    c.yfov = yfov;
    c.znear = 0.05f;
    c.zfar = zfar;
    return c;
}

// Keys with odd numbers in every field, so that "exact" means something.
std::vector<Camera> oddPathKeys() {
    return {pathKey({1.0f / 3.0f, 1.7f, 24.1f}, {0.3f, 2.2f, -3.7f}, 0.9f, 100.0f),
            pathKey({12.8f, 1.9f, 0.123f}, {5.0f, 2.5f, -8.0f}, 1.1f, 250.0f),
            pathKey({-4.0f, 12.5f, -2.0f}, {-10.6f, 7.5f, 6.0f}, 0.7f, 0.0f),
            pathKey({-7.5f, 9.0f, 9.0f}, {-10.0f, 8.0f, 20.0f}, 0.8f, 0.0f)};
}

void expectSameCamera(const Camera& a, const Camera& b, const std::string& what) {
    EXPECT_EQ(a.position, b.position) << what;
    EXPECT_EQ(a.target, b.target) << what;
    EXPECT_EQ(a.up, b.up) << what;
    EXPECT_EQ(a.yfov, b.yfov) << what;
    EXPECT_EQ(a.znear, b.znear) << what;
    EXPECT_EQ(a.zfar, b.zfar) << what;
}

std::vector<double> defaultTimes(size_t n) {
    std::vector<double> t;
    for (size_t i = 0; i < n; ++i)
        t.push_back(double(i));
    return t;
}

json validPathJson() {
    return cameraPathToJson(oddPathKeys(), 7, Interpolation::CatmullRom);
}

// The error for `j` must be exactly `expected` (one line, naming "p.json").
void expectPathRefused(const json& j, const std::string& expected) {
    Result<std::vector<Camera>> views = cameraPathFromJson(j, "p.json");
    ASSERT_FALSE(views.ok()) << j.dump();
    EXPECT_EQ(views.error(), expected);
    EXPECT_EQ(views.error().find('\n'), std::string::npos);
}

} // namespace

TEST(CameraPath, ViewsAtKeyTimesAreTheKeysExactly) {
    const std::vector<Camera> keys = oddPathKeys();
    for (Interpolation interpolation : {Interpolation::Linear, Interpolation::CatmullRom}) {
        // Default times 0..3, 3 views a segment: keys at views 0, 3, 6, 9.
        Result<std::vector<Camera>> views =
            sampleCameraPath(keys, defaultTimes(keys.size()), 10, interpolation, "x");
        ASSERT_TRUE(views.ok()) << views.error();
        ASSERT_EQ(views->size(), 10u);
        for (size_t k = 0; k < keys.size(); ++k)
            expectSameCamera((*views)[3 * k], keys[k], "key " + std::to_string(k));
        // Uneven times given in the file: 0, 0.25, 1.5, 3 hit by 13 views (a step of 0.25).
        views = sampleCameraPath(keys, {0.0, 0.25, 1.5, 3.0}, 13, interpolation, "x");
        ASSERT_TRUE(views.ok()) << views.error();
        for (auto [view, key] : {std::pair{0, 0}, {1, 1}, {6, 2}, {12, 3}})
            expectSameCamera((*views)[size_t(view)], keys[size_t(key)],
                             "timed key " + std::to_string(key));
    }
    Result<std::vector<Camera>> one =
        sampleCameraPath(keys, defaultTimes(keys.size()), 1, Interpolation::CatmullRom, "x");
    ASSERT_TRUE(one.ok()) << one.error();
    ASSERT_EQ(one->size(), 1u);
    expectSameCamera(one->front(), keys.front(), "frames 1");
}

TEST(CameraPath, ViewsAreEvenlySpacedInTime) {
    // Two keys 10 m apart: both interpolations move the same distance every view.
    const std::vector<Camera> keys = {pathKey({0, 2, 0}, {0, 2, -5}),
                                      pathKey({10, 2, 0}, {10, 2, -5})};
    for (Interpolation interpolation : {Interpolation::Linear, Interpolation::CatmullRom}) {
        Result<std::vector<Camera>> views =
            sampleCameraPath(keys, {0.0, 1.0}, 11, interpolation, "x");
        ASSERT_TRUE(views.ok()) << views.error();
        for (size_t i = 0; i < 11; ++i) {
            EXPECT_NEAR((*views)[i].position.x, float(i), 1e-5f)
                << interpolationName(interpolation);
            EXPECT_NEAR((*views)[i].target.x, float(i), 1e-5f);
        }
    }
    // Keys at times 0, 1, 4: view 2 of 5 (time 2) is a third of the way from key 1 to key 2,
    // in every linear field.
    const std::vector<Camera> timed = {pathKey({0, 0, 0}, {0, 0, -1}, 0.6f, 10.0f),
                                       pathKey({3, 0, 0}, {3, 0, -1}, 0.9f, 40.0f),
                                       pathKey({6, 3, 0}, {6, 3, -1}, 1.2f, 70.0f)};
    Result<std::vector<Camera>> views =
        sampleCameraPath(timed, {0.0, 1.0, 4.0}, 5, Interpolation::Linear, "x");
    ASSERT_TRUE(views.ok()) << views.error();
    EXPECT_NEAR((*views)[2].position.x, 4.0f, 1e-5f);
    EXPECT_NEAR((*views)[2].position.y, 1.0f, 1e-5f);
    EXPECT_NEAR((*views)[2].yfov, 1.0f, 1e-6f);
    EXPECT_NEAR((*views)[2].zfar, 50.0f, 1e-4f);
}

// Keys on a line at x = 0, 1, 10, 11: uniform Catmull-Rom runs backwards on the short first
// segment (its tangent at x = 1 is half the long chord); centripetal stays monotonic.
TEST(CameraPath, CentripetalDoesNotRunBackwards) {
    std::vector<Camera> keys;
    for (float x : {0.0f, 1.0f, 10.0f, 11.0f})
        keys.push_back(pathKey({x, 2, 0}, {x, 2, -5}));
    Result<std::vector<Camera>> views =
        sampleCameraPath(keys, defaultTimes(4), 301, Interpolation::CatmullRom, "x");
    ASSERT_TRUE(views.ok()) << views.error();
    for (size_t i = 1; i < views->size(); ++i)
        ASSERT_GE((*views)[i].position.x, (*views)[i - 1].position.x) << "view " << i;
}

// A key repeated holds the camera still over its segment while the target may move on.
TEST(CameraPath, RepeatedPositionHoldsStill) {
    const std::vector<Camera> keys = {pathKey({0, 2, 0}, {0, 2, -5}),
                                      pathKey({4, 2, 0}, {4, 2, -5}), pathKey({4, 2, 0}, {9, 2, 0}),
                                      pathKey({8, 2, 0}, {8, 2, 5})};
    Result<std::vector<Camera>> views =
        sampleCameraPath(keys, defaultTimes(4), 31, Interpolation::CatmullRom, "x");
    ASSERT_TRUE(views.ok()) << views.error();
    for (size_t i = 10; i <= 20; ++i)
        EXPECT_EQ((*views)[i].position, keys[1].position) << "view " << i;
}

TEST(CameraPath, JsonRoundTrip) {
    Result<std::vector<Camera>> views = cameraPathFromJson(validPathJson(), "x");
    ASSERT_TRUE(views.ok()) << views.error();
    Result<std::vector<Camera>> direct =
        sampleCameraPath(oddPathKeys(), defaultTimes(4), 7, Interpolation::CatmullRom, "x");
    ASSERT_TRUE(direct.ok()) << direct.error();
    ASSERT_EQ(views->size(), 7u);
    for (size_t i = 0; i < 7; ++i)
        expectSameCamera((*views)[i], (*direct)[i], "view " + std::to_string(i));
    const std::string path = testTempPath("camera_path.json").string();
    ASSERT_TRUE(writeCameraPath(path, oddPathKeys(), 7, Interpolation::CatmullRom).ok());
    Result<std::vector<Camera>> read = readCameraPath(path);
    ASSERT_TRUE(read.ok()) << read.error();
    for (size_t i = 0; i < 7; ++i)
        expectSameCamera((*read)[i], (*direct)[i], "file view " + std::to_string(i));
    fs::remove(path);
}

TEST(CameraPath, StrictParsingErrors) {
    json j = validPathJson();
    j["speed"] = 2;
    expectPathRefused(j, "p.json: unknown key \"speed\"");
    j = validPathJson();
    j.erase("interpolation");
    expectPathRefused(j, "p.json: missing \"interpolation\"");
    j = validPathJson();
    j["keys"][1]["fov"] = 60;
    expectPathRefused(j, "p.json: key 1: unknown key \"fov\"");
    j = validPathJson();
    j["frames"] = 0;
    expectPathRefused(j, "p.json: \"frames\" must be an integer from 1 to 100000 (got 0)");
    j["frames"] = 2.5;
    expectPathRefused(j, "p.json: \"frames\" must be an integer from 1 to 100000 (got 2.5)");
    j = validPathJson();
    j["interpolation"] = "cubic";
    expectPathRefused(j, "p.json: \"interpolation\" must be \"linear\" or \"catmull-rom\" (got "
                         "\"cubic\")");
    j = validPathJson();
    j["schema"] = "triptych.camera/1";
    expectPathRefused(j, "p.json: \"schema\" must be \"triptych.camera_path/1\" (got "
                         "\"triptych.camera/1\")");
    j = validPathJson();
    j["keys"] = json::array();
    expectPathRefused(j, "p.json: \"keys\" must be a non-empty array of cameras");
    j = validPathJson();
    for (size_t k = 0; k < 4; ++k)
        j["keys"][k]["time"] = std::vector<double>{0.0, 1.0, 1.0, 2.0}[k];
    expectPathRefused(j, "p.json: key 2: \"time\" 1.0 must be greater than the previous key's 1.0");
    j = validPathJson();
    j["keys"][0]["time"] = 0.0;
    expectPathRefused(j, "p.json: key 1: \"time\" must be given for every key or for none");
    j = validPathJson();
    j["keys"][2]["target"] = j["keys"][2]["position"];
    expectPathRefused(j, "p.json: key 2: \"position\" and \"target\" are the same point");
}

TEST(CameraPath, SamplingRefusesTimesThatDoNotIncrease) {
    const std::vector<Camera> keys = {pathKey({0, 0, 0}, {0, 0, -1}),
                                      pathKey({1, 0, 0}, {1, 0, -1})};
    Result<std::vector<Camera>> views =
        sampleCameraPath(keys, {1.0, 1.0}, 3, Interpolation::Linear, "x");
    ASSERT_FALSE(views.ok());
    EXPECT_EQ(views.error(), "x: key 1: times must be finite and strictly increasing");
}

// Keys that are each valid but meet half way: position and target cross at view 1.
TEST(CameraPath, RefusesAnInvalidView) {
    const std::vector<Camera> keys = {pathKey({0, 0, 0}, {2, 0, 0}), pathKey({2, 0, 0}, {0, 0, 0})};
    expectPathRefused(cameraPathToJson(keys, 3, Interpolation::Linear),
                      "p.json: view 1: \"position\" and \"target\" are the same point");
}

TEST(CameraPath, FileErrorsNameTheFile) {
    const std::string missing = testTempPath("no_such_path.json").string();
    Result<std::vector<Camera>> views = readCameraPath(missing);
    ASSERT_FALSE(views.ok());
    EXPECT_EQ(views.error(), missing + ": camera path file not found");
    const std::string bad = testTempPath("bad_path.json").string();
    std::ofstream(bad) << "{\"schema\": ";
    views = readCameraPath(bad);
    ASSERT_FALSE(views.ok());
    EXPECT_EQ(views.error(), bad + ": not valid JSON");
    fs::remove(bad);
}

// The path over the built-in courtyard (docs/recipes/courtyard_path.json) reads, with the 120
// views or more the benchmark asks for. With TRIPTYCH_WRITE_PATH_VIEWS=DIR it also writes
// every 10th view there as a camera file, to look at with `triptych render --camera`.
TEST(CameraPath, CourtyardRecipeReads) {
    // The source tree, found from a folder the build names (tests/fuzz/regressions).
    const fs::path recipe =
        fs::path(TP_FUZZ_REGRESSIONS) / "../../../docs/recipes/courtyard_path.json";
    const auto begin = std::chrono::steady_clock::now();
    Result<std::vector<Camera>> views = readCameraPath(recipe.lexically_normal().string());
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
    ASSERT_TRUE(views.ok()) << views.error();
    EXPECT_GE(views->size(), 120u);
    std::printf("[ timing ] courtyard_path.json, %zu views: %.3f ms\n", views->size(), ms);
    const char* dir = std::getenv("TRIPTYCH_WRITE_PATH_VIEWS");
    for (size_t i = 0; dir && i < views->size(); i += 10) {
        const std::string file = std::string(dir) + "/view" + std::to_string(i) + ".json";
        ASSERT_TRUE(writeCameraFile(file, (*views)[i]).ok()) << file;
    }
}
