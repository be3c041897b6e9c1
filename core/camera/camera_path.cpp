// Camera path files (camera_path.h): the JSON form, strict as camera files are (a misspelt
// key must not be ignored), and the choice between it and a glTF file's animated camera.
#include "core/camera/camera_path.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/camera/camera_file.h"
#include "core/util/files.h"

namespace tp {
namespace {

using nlohmann::json;

// A path of a thousand keys is ~250 KB; anything this large is the wrong file (and reading
// /dev/zero or a huge log must not hang or exhaust memory).
constexpr uintmax_t kMaxPathFileBytes = 16u << 20;

const std::array<const char*, 4> kPathKeys = {"schema", "frames", "interpolation", "keys"};

Status checkPathKeys(const json& j, const std::string& where) {
    if (!j.is_object()) return Error{where + ": a camera path must be a JSON object"};
    for (const char* key : kPathKeys)
        if (!j.contains(key)) return Error{where + ": missing \"" + key + "\""};
    for (const auto& item : j.items())
        if (std::find_if(kPathKeys.begin(), kPathKeys.end(),
                         [&](const char* k) { return item.key() == k; }) == kPathKeys.end())
            return Error{where + ": unknown key \"" + item.key() + "\""};
    const json& schema = j.at("schema");
    if (!schema.is_string() || schema.get<std::string>() != kCameraPathSchema)
        return Error{where + ": \"schema\" must be \"" + kCameraPathSchema + "\" (got " +
                     schema.dump() + ")"};
    return {};
}

Result<uint32_t> readPathFrames(const json& j, const std::string& where) {
    const json& v = j.at("frames");
    const bool integer =
        v.is_number_integer() ||
        (v.is_number_float() && std::nearbyint(v.get<double>()) == v.get<double>());
    const double n = v.is_number() ? v.get<double>() : 0.0;
    if (!integer || !(n >= 1.0 && n <= double(kMaxPathFrames)))
        return Error{where + ": \"frames\" must be an integer from 1 to " +
                     std::to_string(kMaxPathFrames) + " (got " + v.dump() + ")"};
    return uint32_t(n);
}

Result<Interpolation> readPathInterpolation(const json& j, const std::string& where) {
    const json& v = j.at("interpolation");
    if (v.is_string() && v.get<std::string>() == interpolationName(Interpolation::Linear))
        return Interpolation::Linear;
    if (v.is_string() && v.get<std::string>() == interpolationName(Interpolation::CatmullRom))
        return Interpolation::CatmullRom;
    return Error{where + ": \"interpolation\" must be \"linear\" or \"catmull-rom\" (got " +
                 v.dump() + ")"};
}

// The keys and their times ("time" taken off each key before it is read as a camera).
Status readPathKeys(const json& j, const std::string& where, std::vector<Camera>& keys,
                    std::vector<double>& times) {
    const json& list = j.at("keys");
    if (!list.is_array() || list.empty())
        return Error{where + ": \"keys\" must be a non-empty array of cameras"};
    const bool timed = list[0].is_object() && list[0].contains("time");
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string label = where + ": key " + std::to_string(i);
        json key = list[i];
        const bool hasTime = key.is_object() && key.contains("time");
        if (hasTime != timed)
            return Error{label + ": \"time\" must be given for every key or for none"};
        double t = double(i);
        if (hasTime) {
            const json& v = key.at("time");
            t = v.is_number() ? v.get<double>() : NAN;
            if (!std::isfinite(t)) return Error{label + ": \"time\" must be a finite number"};
            if (i > 0 && !(t > times.back()))
                return Error{label + ": \"time\" " + json(t).dump() +
                             " must be greater than the previous key's " +
                             json(times.back()).dump()};
            key.erase("time");
        }
        Result<Camera> camera = cameraFromJson(key, label);
        if (!camera) return Error{camera.error()};
        keys.push_back(*camera);
        times.push_back(t);
    }
    return {};
}

Result<std::vector<Camera>> parseCameraPath(const json& j, const std::string& where) {
    if (Status s = checkPathKeys(j, where); !s) return Error{s.error()};
    Result<uint32_t> frames = readPathFrames(j, where);
    if (!frames) return Error{frames.error()};
    Result<Interpolation> interpolation = readPathInterpolation(j, where);
    if (!interpolation) return Error{interpolation.error()};
    std::vector<Camera> keys;
    std::vector<double> times;
    if (Status s = readPathKeys(j, where, keys, times); !s) return Error{s.error()};
    return sampleCameraPath(keys, times, *frames, *interpolation, where);
}

bool isGltfPathName(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext)
        c = char(std::tolower(uint8_t(c)));
    return ext == ".gltf" || ext == ".glb";
}

Result<json> readPathJsonFile(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return Error{path + ": camera path file not found"};
    if (!std::filesystem::is_regular_file(path, ec)) return Error{path + ": not a regular file"};
    if (uintmax_t size = std::filesystem::file_size(path, ec); !ec && size > kMaxPathFileBytes)
        return Error{path + ": " + std::to_string(size) + " bytes, too large for a camera path"};
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{path + ": cannot open (" + std::strerror(errno) + ")"};
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return Error{path + ": read failed"};
    json j = json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded()) return Error{path + ": not valid JSON"};
    return j;
}

} // namespace

Result<std::vector<Camera>> cameraPathFromJson(const json& j, const std::string& where) {
    // Messages quote the file's keys: a control character must not break the line.
    Result<std::vector<Camera>> views = parseCameraPath(j, where);
    if (!views) return Error{printableLine(views.error())};
    return views;
}

Result<std::vector<Camera>> readCameraPath(const std::string& path, uint32_t gltfFrames) {
    if (isGltfPathName(path)) return readGltfCameraPath(path, gltfFrames);
    Result<json> j = readPathJsonFile(path);
    if (!j) return Error{printableLine(j.error())};
    return cameraPathFromJson(*j, path);
}

json cameraPathToJson(const std::vector<Camera>& keys, uint32_t frames,
                      Interpolation interpolation) {
    json j = json::object();
    j["schema"] = kCameraPathSchema;
    j["frames"] = frames;
    j["interpolation"] = interpolationName(interpolation);
    j["keys"] = json::array();
    for (const Camera& key : keys)
        j["keys"].push_back(cameraToJson(key));
    return j;
}

Status writeCameraPath(const std::string& path, const std::vector<Camera>& keys, uint32_t frames,
                       Interpolation interpolation) {
    return writeTextFile(path, cameraPathToJson(keys, frames, interpolation).dump(2) + "\n");
}

} // namespace tp
