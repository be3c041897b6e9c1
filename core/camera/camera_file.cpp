#include "core/camera/camera_file.h"

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <glm/gtc/constants.hpp>

#include "core/camera/camera.h"
#include "core/util/files.h"

namespace tp {

namespace {

using nlohmann::json;

// A camera file is a few hundred bytes; anything this large is the wrong file (and reading
// /dev/zero or a huge log must not hang or exhaust memory).
constexpr uintmax_t kMaxCameraFileBytes = 64 * 1024;
// sin of the smallest angle allowed between `up` and the view direction: below ~0.06 degrees
// the camera's right vector (their cross product) is mostly rounding error.
constexpr double kMinUpSine = 1e-3;

// The widest image --res can ask for, as width / height: sides up to maxImageDimension2D
// (16384 on lavapipe, 32768 at most on the GPUs we know) over one pixel.
constexpr float kMaxAspect = 32768.0f;

const std::array<const char*, 7> kKeys = {"schema",       "position", "target", "up",
                                          "yfov_degrees", "znear",    "zfar"};

// Shortest round-trip text of a number (std::to_string would print "180.000000").
std::string num(double v) {
    return json(v).dump();
}

// The shortest decimal that reads back as the same float: 1.8, not 1.7999999523162842 (the
// file is for people to read and edit too).
double shortest(float f) {
    char text[32];
    const std::to_chars_result r = std::to_chars(text, text + sizeof text, f);
    return std::strtod(std::string(text, r.ptr).c_str(), nullptr);
}

// Degrees with as few digits as give back exactly `radians` when read.
double shortestDegrees(float radians) {
    const double exact = double(radians) * 180.0 / glm::pi<double>();
    for (int digits = 6; digits < 17; ++digits) {
        char text[40];
        std::snprintf(text, sizeof text, "%.*g", digits, exact);
        const double degrees = std::strtod(text, nullptr);
        if (float(degrees * glm::pi<double>() / 180.0) == radians) return degrees;
    }
    return exact;
}

json vecJson(const glm::vec3& v) {
    return json::array({shortest(v.x), shortest(v.y), shortest(v.z)});
}

// A JSON number that is also a finite float (1e300 is finite as a double, not as a float).
bool finiteFloat(const json& v, double& out) {
    if (!v.is_number()) return false;
    out = v.get<double>();
    return std::isfinite(out) && std::fabs(out) <= 3.0e38;
}

bool finiteFloat(const json& v, float& out) {
    double d = 0.0;
    if (!finiteFloat(v, d)) return false;
    out = float(d);
    return true;
}

Status readVec(const json& j, const char* key, const std::string& where, glm::vec3& out) {
    const json& v = j.at(key);
    bool ok = v.is_array() && v.size() == 3;
    for (int i = 0; ok && i < 3; ++i)
        ok = finiteFloat(v[i], out[i]);
    if (!ok) return Error{where + ": \"" + key + "\" must be an array of 3 finite numbers"};
    return {};
}

template <class T>
Status readNumber(const json& j, const char* key, const std::string& where, T& out) {
    if (!finiteFloat(j.at(key), out))
        return Error{where + ": \"" + key + "\" must be a finite number"};
    return {};
}

Status checkKeys(const json& j, const std::string& where) {
    if (!j.is_object()) return Error{where + ": a camera must be a JSON object"};
    for (const char* key : kKeys)
        if (!j.contains(key)) return Error{where + ": missing \"" + key + "\""};
    for (const auto& item : j.items()) {
        bool known = false;
        for (const char* key : kKeys)
            known = known || item.key() == key;
        if (!known) return Error{where + ": unknown key \"" + item.key() + "\""};
    }
    const json& schema = j.at("schema");
    if (!schema.is_string() || schema.get<std::string>() != kCameraSchema)
        return Error{where + ": \"schema\" must be \"" + kCameraSchema + "\" (got " +
                     schema.dump() + ")"};
    return {};
}

template <class M> bool finiteMatrix(const M& m) {
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row)
            if (!std::isfinite(m[col][row])) return false;
    return true;
}

// The matrices themselves, in fp32 as camera.cpp builds them (found by
// tests/fuzz/fuzz_camera.cpp): numbers within fp32 can still overflow there. A position near
// 3e38 overflows the view's translation, a yfov of 1e-40 degrees is 0 as a float (1/tan(0)),
// a znear of 1e20 times a zfar of 2e20 overflows the depth terms.
Status checkMatrices(Camera c, double yfovDegrees, const std::string& where) {
    c.yfov = float(yfovDegrees * glm::pi<double>() / 180.0);
    if (!finiteMatrix(viewMatrix(c)))
        return Error{where +
                     ": \"position\" is too far from the origin: the view matrix overflows fp32"};
    for (float aspect : {1.0f / kMaxAspect, kMaxAspect}) {
        const glm::mat4 p = reverseZPerspective(c.yfov, aspect, c.znear, c.zfar);
        if (!std::isfinite(p[0][0]) || !std::isfinite(p[1][1]))
            return Error{where + ": \"yfov_degrees\" " + num(yfovDegrees) +
                         " is too small: the projection overflows fp32"};
        // Just below 180 degrees, the float nearest the angle in radians can be past pi.
        if (!(p[1][1] > 0.0f))
            return Error{where + ": \"yfov_degrees\" " + num(yfovDegrees) +
                         " is too close to 180: the projection turns over in fp32"};
        if (!finiteMatrix(p))
            return Error{where + ": \"znear\" " + num(shortest(c.znear)) + " and \"zfar\" " +
                         num(shortest(c.zfar)) + " overflow the projection's depth terms in fp32"};
    }
    return {};
}

// The geometry a view matrix and a projection need (computed in double, as camera.cpp does).
Status checkCamera(const Camera& c, double yfovDegrees, const std::string& where) {
    glm::dvec3 dir = glm::dvec3(c.target) - glm::dvec3(c.position);
    if (glm::length(dir) == 0.0)
        return Error{where + ": \"position\" and \"target\" are the same point"};
    if (glm::length(glm::dvec3(c.up)) == 0.0) return Error{where + ": \"up\" is the zero vector"};
    double sine = glm::length(glm::cross(glm::normalize(dir), glm::normalize(glm::dvec3(c.up))));
    if (!(sine >= kMinUpSine))
        return Error{where + ": \"up\" is parallel to the view direction (target - position)"};
    if (!(yfovDegrees > 0.0 && yfovDegrees < 180.0))
        return Error{where + ": \"yfov_degrees\" must be between 0 and 180 (exclusive), got " +
                     num(yfovDegrees)};
    if (!(c.znear > 0.0f)) return Error{where + ": \"znear\" must be > 0, got " + num(c.znear)};
    if (c.zfar != 0.0f && !(c.zfar > c.znear))
        return Error{where + ": \"zfar\" must be 0 (infinite) or greater than \"znear\", got " +
                     num(c.zfar)};
    return checkMatrices(c, yfovDegrees, where);
}

Result<Camera> parseCamera(const json& j, const std::string& where) {
    if (Status s = checkKeys(j, where); !s) return Error{s.error()};
    Camera c;
    double yfovDegrees = 0.0; // double: the float radians come back exactly
    for (Status s :
         {readVec(j, "position", where, c.position), readVec(j, "target", where, c.target),
          readVec(j, "up", where, c.up), readNumber(j, "yfov_degrees", where, yfovDegrees),
          readNumber(j, "znear", where, c.znear), readNumber(j, "zfar", where, c.zfar)})
        if (!s) return Error{s.error()};
    if (Status s = checkCamera(c, yfovDegrees, where); !s) return Error{s.error()};
    c.yfov = float(yfovDegrees * glm::pi<double>() / 180.0);
    return c;
}

} // namespace

json cameraToJson(const Camera& camera) {
    // Degrees in the file (what people type), radians in Camera; every number reads back as
    // exactly the float it was written from.
    json j = json::object();
    j["schema"] = kCameraSchema;
    j["position"] = vecJson(camera.position);
    j["target"] = vecJson(camera.target);
    j["up"] = vecJson(camera.up);
    j["yfov_degrees"] = shortestDegrees(camera.yfov);
    j["znear"] = shortest(camera.znear);
    j["zfar"] =
        camera.zfar > 0.0f ? shortest(camera.zfar) : 0.0; // Camera's "zfar <= 0" is the file's 0
    return j;
}

Result<Camera> cameraFromJson(const json& j, const std::string& where) {
    // Messages quote the file's keys: a control character must not break the line.
    Result<Camera> c = parseCamera(j, where);
    if (!c) return Error{printableLine(c.error())};
    return c;
}

Result<Camera> readCameraFile(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return Error{printableLine(path + ": camera file not found")};
    if (!std::filesystem::is_regular_file(path, ec))
        return Error{printableLine(path + ": not a regular file")};
    if (uintmax_t size = std::filesystem::file_size(path, ec); !ec && size > kMaxCameraFileBytes)
        return Error{printableLine(path + ": " + std::to_string(size) +
                                   " bytes, too large for a camera file")};
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{printableLine(path + ": cannot open (" + std::strerror(errno) + ")")};
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return Error{printableLine(path + ": read failed")};
    json j = json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded()) return Error{printableLine(path + ": not valid JSON")};
    return cameraFromJson(j, path);
}

Status writeCameraFile(const std::string& path, const Camera& camera) {
    return writeTextFile(path, cameraToJson(camera).dump(2) + "\n");
}

} // namespace tp
