// Seeded light generation and the lights JSON format.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/scene/lights.h"

using namespace tp;

namespace {

const Aabb kBounds{{-15.0f, 0.0f, -30.0f}, {15.0f, 13.0f, 30.0f}};

bool sameBits(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}
bool sameBits(const glm::vec3& a, const glm::vec3& b) {
    return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z);
}
bool identical(const Light& a, const Light& b) {
    return a.type == b.type && sameBits(a.position, b.position) &&
           sameBits(a.direction, b.direction) && sameBits(a.color, b.color) &&
           sameBits(a.intensity, b.intensity) && sameBits(a.range, b.range) &&
           sameBits(a.innerConeAngle, b.innerConeAngle) &&
           sameBits(a.outerConeAngle, b.outerConeAngle);
}
bool identical(const std::vector<Light>& a, const std::vector<Light>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (!identical(a[i], b[i])) return false;
    return true;
}

LightGenOptions mixed(uint32_t count, uint64_t seed) {
    LightGenOptions o;
    o.count = count;
    o.seed = seed;
    o.pointWeight = 2.0f;
    o.spotWeight = 1.0f;
    o.directionalWeight = 0.2f;
    return o;
}

// Expects a one-line error naming `name` and containing `what`.
void expectError(const std::string& json, const std::string& what) {
    auto r = lightsFromJson(json, "lights.json");
    ASSERT_FALSE(r.ok()) << json;
    EXPECT_EQ(r.error().rfind("lights.json: ", 0), 0u) << r.error();
    EXPECT_EQ(r.error().find('\n'), std::string::npos) << r.error();
    EXPECT_NE(r.error().find(what), std::string::npos) << r.error();
}

std::string oneLight(const std::string& fields) {
    return "{\"version\":1,\"lights\":[{" + fields + "}]}";
}

} // namespace

TEST(LightsGenerate, SameSeedSameLightsOtherSeedOthers) {
    auto a = generateLights(kBounds, mixed(1000, 7));
    auto b = generateLights(kBounds, mixed(1000, 7));
    auto c = generateLights(kBounds, mixed(1000, 8));
    EXPECT_TRUE(identical(a, b));
    ASSERT_EQ(c.size(), a.size());
    size_t same = 0;
    for (size_t i = 0; i < a.size(); ++i)
        same += sameBits(a[i].position, c[i].position);
    EXPECT_EQ(same, 0u);
}

TEST(LightsGenerate, CountsAndPlacement) {
    EXPECT_TRUE(generateLights(kBounds, mixed(0, 1)).empty());
    EXPECT_EQ(generateLights(kBounds, mixed(1, 1)).size(), 1u);
    auto lights = generateLights(kBounds, mixed(65536, 3));
    ASSERT_EQ(lights.size(), 65536u);
    const glm::vec3 margin = kBounds.extent() * 0.02f;
    const float diag = glm::length(kBounds.extent());
    size_t types[3] = {0, 0, 0};
    for (const Light& l : lights) {
        ++types[uint32_t(l.type)];
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(l.position, kBounds.min + margin)) &&
                    glm::all(glm::lessThanEqual(l.position, kBounds.max - margin)));
        EXPECT_GE(l.range, 0.04f * diag * 0.9999f);
        EXPECT_LE(l.range, 0.12f * diag * 1.0001f);
        float s = std::max({l.color.r, l.color.g, l.color.b});
        float sat = 1.0f - std::min({l.color.r, l.color.g, l.color.b}) / s;
        EXPECT_NEAR(s, 1.0f, 1e-5f);
        EXPECT_GE(sat, 0.3f - 1e-4f);
        EXPECT_LE(sat, 0.7f + 1e-4f);
        if (l.type == LightType::Point) {
            EXPECT_GE(l.intensity, 0.3f * l.range * l.range * 0.9999f);
            EXPECT_LE(l.intensity, 1.5f * l.range * l.range * 1.0001f);
        }
        if (l.type != LightType::Point) {
            EXPECT_NEAR(glm::length(l.direction), 1.0f, 1e-5f);
            EXPECT_LT(l.direction.y, -0.5f);
        }
        if (l.type == LightType::Spot) {
            EXPECT_GE(l.outerConeAngle, glm::radians(20.0f) * 0.9999f);
            EXPECT_LE(l.outerConeAngle, glm::radians(45.0f) * 1.0001f);
            EXPECT_GE(l.innerConeAngle, 0.6f * l.outerConeAngle * 0.9999f);
            EXPECT_LE(l.innerConeAngle, 0.9f * l.outerConeAngle * 1.0001f);
        }
        if (l.type == LightType::Directional) {
            EXPECT_GE(l.intensity, 0.5f);
            EXPECT_LE(l.intensity, 2.0f);
        }
        if (::testing::Test::HasFailure()) break;
    }
    EXPECT_GT(types[0], 30000u);
    EXPECT_GT(types[1], 15000u);
    EXPECT_GT(types[2], 1000u);
}

TEST(LightsGenerate, ExplicitRanges) {
    LightGenOptions o;
    o.count = 500;
    o.radiusMin = 2.0f;
    o.radiusMax = 3.0f;
    o.intensityMin = 10.0f;
    o.intensityMax = 20.0f;
    for (const Light& l : generateLights(kBounds, o)) {
        EXPECT_EQ(l.type, LightType::Point);
        EXPECT_TRUE(l.range >= 2.0f && l.range <= 3.0f);
        EXPECT_TRUE(l.intensity >= 10.0f && l.intensity <= 20.0f);
    }
}

TEST(LightsJson, RoundTripIsExact) {
    auto lights = generateLights(kBounds, mixed(2000, 11));
    Light odd;
    odd.type = LightType::Spot;
    // Values that stress the decimal round trip, within the bounds a lights file may have.
    odd.position = {0.1f, -1e-7f, 9.9999994e9f};
    odd.direction = {1e-38f, -0.3333333f, 1.0f / 3.0f};
    odd.color = {0.0f, 1e-45f, 123456.79f};
    odd.intensity = 8.0999e9f; // * 123456.79 just under 1e15
    odd.range = std::numeric_limits<float>::min();
    odd.innerConeAngle = 0.0f;
    odd.outerConeAngle = 1.5707963f;
    lights.push_back(odd);
    // Floats whose shortest decimal, read as a double, lands on a midpoint between two floats:
    // read back through that double they would round to their even neighbour.
    Light midpoint = odd;
    uint32_t bits = 0x15ae43fd; // 7.038531e-26
    std::memcpy(&midpoint.color.x, &bits, 4);
    bits = 0x95ae43fd; // -7.038531e-26
    std::memcpy(&midpoint.position.y, &bits, 4);
    lights.push_back(midpoint);
    std::string text = lightsToJson(lights);
    auto back = lightsFromJson(text, "mem");
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_TRUE(identical(*back, lights));
    auto empty = lightsFromJson(lightsToJson({}), "mem");
    ASSERT_TRUE(empty.ok()) << empty.error();
    EXPECT_TRUE(empty->empty());
}

TEST(LightsJson, DefaultsForOptionalFields) {
    auto r = lightsFromJson(
        oneLight("\"type\":\"point\",\"position\":[1,2,3],\"intensity\":5,\"range\":4"), "x");
    ASSERT_TRUE(r.ok()) << r.error();
    EXPECT_EQ((*r)[0].color, glm::vec3(1.0f));
    EXPECT_EQ((*r)[0].range, 4.0f);
    auto d = lightsFromJson(
        oneLight("\"type\":\"directional\",\"direction\":[0,-1,0],\"intensity\":1"), "x");
    ASSERT_TRUE(d.ok()) << d.error();
    EXPECT_EQ((*d)[0].type, LightType::Directional);
}

TEST(LightsJson, BadInputGivesOneLineErrors) {
    const std::string point = "\"type\":\"point\",\"position\":[1,2,3],\"intensity\":5";
    expectError("{\"lights\":[", "parse error");
    expectError("", "parse error");
    expectError("[1,2]", "top level");
    expectError("{\"version\":1}", "(at lights)");
    expectError("{\"lights\":5}", "(at lights)");
    expectError("{\"version\":2,\"lights\":[]}", "(at version)");
    expectError(oneLight(point + ",\"range\":-1"), "negative (at lights[0].range)");
    expectError(oneLight(point + ",\"range\":\"far\""), "(at lights[0].range)");
    expectError(oneLight(point), "missing field (at lights[0].range)");
    expectError(oneLight("\"type\":\"area\",\"intensity\":1"), "unknown light type 'area'");
    expectError(oneLight("\"type\":7"), "(at lights[0].type)");
    expectError(oneLight(point + ",\"range\":1,\"intensity\":-2"), "(at lights[0].intensity)");
    expectError(oneLight(point + ",\"range\":1,\"colour\":[1,1,1]"), "unknown field 'colour'");
    expectError(oneLight("\"type\":\"point\",\"position\":[1,2],\"intensity\":5,\"range\":1"),
                "(at lights[0].position)");
    expectError(oneLight(point + ",\"range\":1e300"), "not finite");
    expectError(oneLight(point + ",\"range\":1e999"), "lights.json");
    expectError(oneLight("\"type\":\"spot\",\"position\":[0,0,0],\"direction\":[0,0,0],"
                         "\"intensity\":1,\"range\":1"),
                "(at lights[0].direction)");
    expectError(
        oneLight("\"type\":\"spot\",\"position\":[0,0,0],\"direction\":[0,-1,0],\"intensity\":1,"
                 "\"range\":1,\"inner_cone\":0.8,\"outer_cone\":0.5"),
        "(at lights[0].inner_cone)");
    expectError(
        "{\"lights\":[{\"type\":\"point\",\"position\":[0,0,0],\"intensity\":1,\"range\":1}, 3]}",
        "(at lights[1])");
}

// Absurd values and unknown names: each bound (lights.h) refused just past it, accepted at it.
TEST(LightsJson, AbsurdValuesAndUnknownNames) {
    const std::string at = "\"type\":\"point\",\"intensity\":5,\"range\":2,\"position\":";
    expectError("{\"version\":1,\"lights\":[],\"colour\":1}",
                "unknown field 'colour' (at top level");
    expectError(oneLight(at + "[2e10,0,0]"), "at most 1e10 in magnitude (at lights[0].position)");
    expectError(oneLight(at + "[0,-2e10,0]"), "(at lights[0].position)");
    EXPECT_TRUE(lightsFromJson(oneLight(at + "[1e10,-1e10,0]"), "x").ok());
    const std::string p = "\"type\":\"point\",\"position\":[0,1,0],";
    expectError(oneLight(p + "\"intensity\":5,\"range\":0"),
                "must be positive (at lights[0].range)");
    expectError(oneLight(p + "\"intensity\":5,\"range\":2e10"),
                "at most 1e10 (at lights[0].range)");
    expectError(oneLight(p + "\"intensity\":2e15,\"range\":1"), "(at lights[0].intensity)");
    expectError(oneLight(p + "\"intensity\":1e14,\"range\":1,\"color\":[0,20,1]"),
                "brightest color channel must be at most 1e15");
    EXPECT_TRUE(lightsFromJson(oneLight(p + "\"intensity\":1e15,\"range\":1e10"), "x").ok());
    expectError(oneLight(p + "\"intensity\":\"5\",\"range\":1"), "expected a number, got string");
    expectError(oneLight(p + "\"intensity\":true,\"range\":1"), "expected a number, got boolean");
    expectError(oneLight(p + "\"intensity\":null,\"range\":1"), "(at lights[0].intensity)");
    expectError(oneLight("\"type\":\"directional\",\"direction\":[0,-1e-9,0],\"intensity\":1"),
                "(at lights[0].direction)");
    expectError(oneLight("\"type\":\"POINT\",\"intensity\":1"), "unknown light type 'POINT'");
    expectError(std::string(100000, '['), "lights.json: ");
    expectError("{\"lights\":[]} trailing", "parse error");
    // Found by the fuzzer: a key with an escaped newline made a two-line message.
    expectError(oneLight("\"type\":\"point\",\"int\\nsity\":5"), "unknown field 'int sity'");
    expectError(oneLight("\"type\":\"\\u001b[31mred\""), "unknown light type ' [31mred'");
    expectError("{\"lights\":[{\"type\":\"point\",\"position\":[NaN,0,0]}]}", "parse error");
}

TEST(LightsJson, TooManyLights) {
    std::string text = "{\"lights\":[";
    text.reserve(3000020);
    for (int i = 0; i <= 1000000; ++i)
        text += i ? ",{}" : "{}";
    text += "]}";
    expectError(text, "at most 1000000");
}

TEST(LightsJson, FileRoundTrip) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("tp_lights_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    auto lights = generateLights(kBounds, mixed(300, 5));
    std::string path = (dir / "lights.json").string();
    Status w = writeLightsFile(path, lights);
    ASSERT_TRUE(w.ok()) << w.error();
    EXPECT_FALSE(fs::exists(path + ".tmp"));
    auto r = readLightsFile(path);
    ASSERT_TRUE(r.ok()) << r.error();
    EXPECT_TRUE(identical(*r, lights));

    auto missing = readLightsFile((dir / "nope.json").string());
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("nope.json"), std::string::npos);
    Status bad = writeLightsFile((dir / "no_such_dir" / "l.json").string(), lights);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().find("l.json"), std::string::npos);
    auto directory = readLightsFile(dir.string());
    ASSERT_FALSE(directory.ok());
    EXPECT_NE(directory.error().find("not a regular file"), std::string::npos) << directory.error();
    std::ofstream(dir / "broken.json") << "{\"lights\":[{\"type\":\"point\"";
    auto broken = readLightsFile((dir / "broken.json").string());
    ASSERT_FALSE(broken.ok());
    EXPECT_EQ(broken.error().rfind((dir / "broken.json").string() + ": ", 0), 0u) << broken.error();
    fs::remove_all(dir);
}
