// Scene, lights and camera from the scene options: what every command and the viewer load.
#include "core/cli/scene_input.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>

#include "core/camera/camera_file.h"
#include "core/scene/gltf_loader.h"
#include "core/scene/procedural.h"

namespace tp::cli {
namespace {

// A whole string as a finite number (strtod accepts "nan", "inf", leading blanks and stops
// at junk; all of that is refused here).
bool parseNumber(const std::string& text, double& out) {
    if (text.empty() || std::isspace(uint8_t(text[0]))) return false;
    char* end = nullptr;
    out = std::strtod(text.c_str(), &end);
    return end != text.c_str() && *end == 0 && std::isfinite(out);
}

std::pair<float, float> parseRange(const std::string& text, const char* option, double limit) {
    const size_t comma = text.find(',');
    double a = 0, b = 0;
    char limitText[32];
    std::snprintf(limitText, sizeof limitText, "%g", limit);
    if (comma == std::string::npos || !parseNumber(text.substr(0, comma), a) ||
        !parseNumber(text.substr(comma + 1), b) || !(a > 0) || !(b >= a) || b > limit)
        throw UsageError(std::string(option) + " '" + text +
                         "': expected MIN,MAX with 0 < MIN <= MAX <= " + limitText);
    return {float(a), float(b)};
}

// Relative weights: finite, not negative, each type named once.
void parseTypes(const std::string& text, LightGenOptions& g) {
    g.pointWeight = g.spotWeight = g.directionalWeight = 0.0f;
    std::stringstream ss(text);
    std::string item, seen = ",";
    while (std::getline(ss, item, ',')) {
        std::string name = item.substr(0, item.find(':'));
        double weight = 1.0;
        if (item.find(':') != std::string::npos) {
            std::string w = item.substr(item.find(':') + 1);
            if (!parseNumber(w, weight) || weight < 0.0 || weight > 1e6)
                throw UsageError("--light-types '" + text + "': bad weight '" + w +
                                 "' (a number from 0 to 1e6)");
        }
        if (seen.find("," + name + ",") != std::string::npos)
            throw UsageError("--light-types '" + text + "': '" + name + "' is listed twice");
        seen += name + ",";
        if (name == "point")
            g.pointWeight = float(weight);
        else if (name == "spot")
            g.spotWeight = float(weight);
        else if (name == "directional")
            g.directionalWeight = float(weight);
        else
            throw UsageError("--light-types: unknown type '" + name +
                             "' (point, spot, directional)");
    }
    if (g.pointWeight + g.spotWeight + g.directionalWeight <= 0.0f)
        throw UsageError("--light-types '" + text + "': all weights are zero");
}

} // namespace

Camera readCameraOption(const std::string& path) {
    Result<Camera> camera = readCameraFile(path);
    if (!camera) throw UsageError("--camera: " + camera.error());
    return *camera;
}

Scene loadScene(const SceneOptions& o, CameraSource* cameraSource) {
    const LightGenOptions g = generatorOptions(o); // checked before any scene is loaded
    std::optional<Camera> camera; // read first: a bad file fails before a large scene loads
    if (!o.cameraFile.empty()) camera = readCameraOption(o.cameraFile);
    CameraSource source;
    Scene scene;
    std::string name = o.scene.empty() ? "builtin:courtyard" : o.scene;
    if (name.rfind("builtin:", 0) == 0) {
        Result<Scene> s = makeBuiltinScene(name.substr(8));
        if (!s) throw UsageError(s.error());
        scene = std::move(*s);
    } else {
        std::vector<std::string> warnings;
        GltfLoadOptions options;
        options.warnings = &warnings;
        options.strict = o.strict;
        options.cameraIndex = &source.gltfCamera;
        Result<Scene> s = loadGltf(name, options);
        if (!s) throw UsageError(s.error());
        for (const std::string& w : warnings)
            std::fprintf(stderr, "triptych: warning: %s\n", w.c_str());
        scene = std::move(*s);
        source.kind = source.gltfCamera >= 0 ? "gltf" : "framed";
    }
    if (camera) {
        scene.camera = *camera;
        source = {"file", -1, o.cameraFile};
    }
    if (cameraSource) *cameraSource = source;
    if (o.dropSceneLights) scene.lights.clear();
    if (!o.lightsFile.empty()) {
        Result<std::vector<Light>> lights = readLightsFile(o.lightsFile);
        if (!lights) throw UsageError(lights.error());
        scene.lights = std::move(*lights);
        return scene;
    }
    std::vector<Light> generated = generateLights(scene.bounds, g);
    scene.lights.insert(scene.lights.end(), generated.begin(), generated.end());
    return scene;
}

LightGenOptions generatorOptions(const SceneOptions& o) {
    if (o.lightCount < 0 || o.lightCount > 1000000)
        throw UsageError("--lights " + std::to_string(o.lightCount) +
                         ": must be between 0 and 1000000");
    LightGenOptions g;
    g.count = uint32_t(o.lightCount);
    g.seed = o.seed;
    parseTypes(o.lightTypes, g);
    if (!o.lightRadius.empty())
        std::tie(g.radiusMin, g.radiusMax) =
            parseRange(o.lightRadius, "--light-radius", kMaxLightRange);
    if (!o.lightIntensity.empty())
        std::tie(g.intensityMin, g.intensityMax) =
            parseRange(o.lightIntensity, "--light-intensity", kMaxLightIntensity);
    return g;
}

} // namespace tp::cli
