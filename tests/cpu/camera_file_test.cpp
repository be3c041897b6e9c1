// Camera files (core/camera/camera_file.h): what is written reads back as the same camera, bit
// for bit, and every kind of hostile input is refused with one line that names the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "core/camera/camera_file.h"
#include "temp_path.h"

using namespace tp;
using nlohmann::json;

namespace {

namespace fs = std::filesystem;

Camera oddCamera() {
    Camera c;
    c.position = {1.0f / 3.0f, -2.5e-7f, 1234.567f};
    c.target = {0.1f, 0.2f, 0.3f};
    c.up = {0.01f, 1.0f, 0.001f};
    c.yfov = 0.7123457f;
    c.znear = 0.0137f;
    c.zfar = 4321.0f;
    return c;
}

void expectSame(const Camera& a, const Camera& b) {
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.target, b.target);
    EXPECT_EQ(a.up, b.up);
    EXPECT_EQ(a.yfov, b.yfov);
    EXPECT_EQ(a.znear, b.znear);
    EXPECT_EQ(a.zfar, b.zfar);
}

json validJson() {
    return cameraToJson(oddCamera());
}

// The error for `j`, which must be one line naming `where` and containing `expected`.
void expectRefused(const json& j, const std::string& expected) {
    Result<Camera> c = cameraFromJson(j, "cam.json");
    ASSERT_FALSE(c.ok()) << j.dump();
    EXPECT_EQ(c.error().rfind("cam.json: ", 0), 0u) << c.error();
    EXPECT_EQ(c.error().find('\n'), std::string::npos) << c.error();
    EXPECT_NE(c.error().find(expected), std::string::npos) << c.error();
}

} // namespace

TEST(CameraFile, JsonRoundTripIsExact) {
    Result<Camera> back = cameraFromJson(validJson(), "x");
    ASSERT_TRUE(back.ok()) << back.error();
    expectSame(oddCamera(), *back);
    // Through the text too: the file stores doubles that give back the same floats.
    back = cameraFromJson(json::parse(validJson().dump()), "x");
    ASSERT_TRUE(back.ok()) << back.error();
    expectSame(oddCamera(), *back);
}

// Random cameras, random bits: every float comes back exactly (degrees included), and the
// numbers are written as short as that allows (1.8, not 1.7999999523162842).
TEST(CameraFile, RoundTripIsExactForManyCameras) {
    uint64_t state = 12345;
    auto next = [&state](float lo,
                         float hi) { // splitmix64, as lights.cpp: the same numbers everywhere
        uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return lo + (hi - lo) * float((z ^ (z >> 31)) >> 40) * (1.0f / 16777216.0f);
    };
    for (int i = 0; i < 2000; ++i) {
        Camera c;
        c.position = {next(-1e4f, 1e4f), next(-1e4f, 1e4f), next(-1e4f, 1e4f)};
        c.target = c.position + glm::vec3(next(0.1f, 1.0f), next(-1.0f, 1.0f), next(0.1f, 1.0f));
        c.up = {next(-0.1f, 0.1f), next(0.5f, 2.0f), next(-0.1f, 0.1f)};
        c.yfov = next(0.01f, 3.1f);
        c.znear = next(1e-5f, 1.0f);
        c.zfar = i % 2 ? 0.0f : c.znear * next(2.0f, 1e6f);
        Result<Camera> back = cameraFromJson(json::parse(cameraToJson(c).dump()), "x");
        ASSERT_TRUE(back.ok()) << back.error();
        expectSame(c, *back);
    }
    Camera c;
    c.position = {0.0f, 1.8f, 25.0f};
    c.yfov = 1.0f;
    const std::string text = cameraToJson(c).dump();
    EXPECT_NE(text.find("[0.0,1.8,25.0]"), std::string::npos) << text;
    EXPECT_NE(text.find("\"yfov_degrees\":57.29578,"), std::string::npos) << text;
}

TEST(CameraFile, FieldsAreNamedAsDocumented) {
    json j = validJson();
    EXPECT_EQ(j["schema"], "triptych.camera/1");
    EXPECT_NEAR(j["yfov_degrees"].get<double>(), 0.7123457 * 180.0 / 3.14159265358979, 1e-5);
    EXPECT_EQ(j["position"].size(), 3u);
    Camera infinite = oddCamera();
    infinite.zfar = -1.0f; // Camera's "infinite" spelling; the file says 0
    EXPECT_EQ(cameraToJson(infinite)["zfar"].get<double>(), 0.0);
    Result<Camera> back = cameraFromJson(cameraToJson(infinite), "x");
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_EQ(back->zfar, 0.0f);
}

TEST(CameraFile, FileRoundTrip) {
    const std::string path = testTempPath("camera_roundtrip.json");
    ASSERT_TRUE(writeCameraFile(path, oddCamera()).ok());
    Result<Camera> back = readCameraFile(path);
    ASSERT_TRUE(back.ok()) << back.error();
    expectSame(oddCamera(), *back);
    fs::remove(path);
}

TEST(CameraFile, RefusesBadStructure) {
    expectRefused(json::array({1, 2}), "must be a JSON object");
    for (const char* key :
         {"schema", "position", "target", "up", "yfov_degrees", "znear", "zfar"}) {
        json j = validJson();
        j.erase(key);
        expectRefused(j, std::string("missing \"") + key + "\"");
    }
    json j = validJson();
    j["postion"] = json::array({0, 0, 0});
    expectRefused(j, "unknown key \"postion\"");
    j = validJson();
    j["schema"] = "triptych.camera/2";
    expectRefused(j, "\"schema\" must be \"triptych.camera/1\"");
    j = validJson();
    j["schema"] = 1;
    expectRefused(j, "\"schema\"");
    j = validJson();
    j["odd\nkey"] = 1;
    expectRefused(j, "unknown key \"odd key\""); // a control character does not break the line
}

TEST(CameraFile, RefusesBadNumbers) {
    auto with = [](const char* key, json value) {
        json j = validJson();
        j[key] = std::move(value);
        return j;
    };
    expectRefused(with("position", json::array({0, 0})),
                  "\"position\" must be an array of 3 finite numbers");
    expectRefused(with("target", json::array({0, "1", 0})),
                  "\"target\" must be an array of 3 finite");
    expectRefused(with("up", json::array({0, 1e300, 0})), "\"up\" must be an array of 3 finite");
    expectRefused(with("up", json::array({0, NAN, 0})), "\"up\" must be an array of 3 finite");
    expectRefused(with("position", 3), "\"position\" must be an array");
    expectRefused(with("yfov_degrees", "60"), "\"yfov_degrees\" must be a finite number");
    expectRefused(with("znear", true), "\"znear\" must be a finite number");
    expectRefused(with("zfar", INFINITY), "\"zfar\" must be a finite number");
}

TEST(CameraFile, RefusesDegenerateCameras) {
    auto with = [](const char* key, json value) {
        json j = validJson();
        j[key] = std::move(value);
        return j;
    };
    json same = validJson();
    same["target"] = same["position"];
    expectRefused(same, "\"position\" and \"target\" are the same point");
    expectRefused(with("up", json::array({0, 0, 0})), "\"up\" is the zero vector");
    json parallel = with("position", json::array({0, 0, 0}));
    parallel["target"] = json::array({0, 0, -5});
    parallel["up"] = json::array({0, 0, 2}); // along the view direction, other way round
    expectRefused(parallel, "\"up\" is parallel to the view direction");
    parallel["up"] = json::array({0, 1e-6, -1}); // within rounding of parallel
    expectRefused(parallel, "\"up\" is parallel");
    parallel["up"] = json::array({0, 0.1, -1}); // tilted, not parallel: fine
    EXPECT_TRUE(cameraFromJson(parallel, "x").ok());
    expectRefused(with("yfov_degrees", 0), "\"yfov_degrees\" must be between 0 and 180");
    expectRefused(with("yfov_degrees", 180), "got 180");
    expectRefused(with("yfov_degrees", -30), "\"yfov_degrees\"");
    expectRefused(with("znear", 0), "\"znear\" must be > 0, got 0");
    expectRefused(with("znear", -0.1), "\"znear\" must be > 0");
    json far = with("znear", 1.0);
    far["zfar"] = 0.5;
    expectRefused(far, "\"zfar\" must be 0 (infinite) or greater than \"znear\", got 0.5");
    far["zfar"] = 1.0;
    expectRefused(far, "\"zfar\"");
    far["zfar"] = -1.0;
    expectRefused(far, "\"zfar\"");
    far["zfar"] = 0.0;
    EXPECT_TRUE(cameraFromJson(far, "x").ok());
}

// Numbers each within fp32 whose matrices are not (found with tests/fuzz/fuzz_camera.cpp;
// its regression inputs, tests/fuzz/regressions/camera, are these).
TEST(CameraFile, RefusesCamerasWhoseMatricesOverflow) {
    json j = json::parse(R"({"schema":"triptych.camera/1","position":[0,0,5],"target":[0,0,0],
                             "up":[0,1,0],"yfov_degrees":45,"znear":1,"zfar":0})");
    ASSERT_TRUE(cameraFromJson(j, "x").ok());
    auto with = [&](const char* key, json value) {
        json k = j;
        k[key] = std::move(value);
        return k;
    };
    expectRefused(with("position", json::array({3e38, 3e38, 3e38})),
                  "\"position\" is too far from the origin: the view matrix overflows fp32");
    expectRefused(with("yfov_degrees", 1e-40),
                  "\"yfov_degrees\" 1e-40 is too small: the projection overflows fp32");
    expectRefused(
        with("yfov_degrees", 179.99999999),
        "\"yfov_degrees\" 179.99999999 is too close to 180: the projection turns over in fp32");
    json depth = with("znear", 1e20);
    depth["zfar"] = 2e20;
    expectRefused(
        depth, "\"znear\" 1e+20 and \"zfar\" 2e+20 overflow the projection's depth terms in fp32");
    depth["zfar"] = 0; // infinite far plane: znear alone is fine
    EXPECT_TRUE(cameraFromJson(depth, "x").ok());
    // Far, but not near fp32's limit: still a camera.
    EXPECT_TRUE(cameraFromJson(with("position", json::array({1e30, -1e30, 1e30})), "x").ok());
}

TEST(CameraFile, RefusesBadFiles) {
    auto refused = [](const std::string& path, const std::string& expected) {
        Result<Camera> c = readCameraFile(path);
        ASSERT_FALSE(c.ok()) << path;
        EXPECT_EQ(c.error().rfind(path + ": ", 0), 0u) << c.error();
        EXPECT_NE(c.error().find(expected), std::string::npos) << c.error();
        EXPECT_EQ(c.error().find('\n'), std::string::npos) << c.error();
    };
    refused(testTempPath("camera_absent.json").string(), "camera file not found");
    refused(fs::temp_directory_path().string(), "not a regular file");
    const fs::path bad = testTempPath("camera_bad.json");
    std::ofstream(bad) << "{\"schema\": \"triptych.camera/1\", ";
    refused(bad.string(), "not valid JSON");
    std::ofstream(bad, std::ios::trunc) << "";
    refused(bad.string(), "not valid JSON");
    std::ofstream(bad, std::ios::trunc) << std::string(100000, ' ');
    refused(bad.string(), "too large for a camera file");
    std::ofstream(bad, std::ios::trunc) << "{\"schema\":\"triptych.camera/1\"}";
    refused(bad.string(), "missing \"position\"");
    fs::remove(bad);
    EXPECT_FALSE(
        writeCameraFile(testTempPath("camera_no/such/dir/cam.json").string(), oddCamera()).ok());
}
