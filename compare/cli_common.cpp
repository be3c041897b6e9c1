#include "compare/cli_common.h"

#include <cmath>
#include <sstream>
#include <cstdio>
#include <filesystem>

#include "core/image/tonemap.h"
#include "core/scene/gltf_loader.h"
#include "core/scene/procedural.h"

namespace tp::cli {
namespace {

std::pair<float, float> parseRange(const std::string& text, const char* option) {
    float a = 0, b = 0;
    char comma = 0;
    if (std::sscanf(text.c_str(), "%f%c%f", &a, &comma, &b) != 3 || comma != ',' || !(a > 0) || !(b >= a) ||
        !std::isfinite(b))
        throw UsageError(std::string(option) + " '" + text + "': expected MIN,MAX with 0 < MIN <= MAX");
    return {a, b};
}

void parseTypes(const std::string& text, LightGenOptions& g) {
    g.pointWeight = g.spotWeight = g.directionalWeight = 0.0f;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        std::string name = item.substr(0, item.find(':'));
        float weight = 1.0f;
        if (item.find(':') != std::string::npos) {
            std::string w = item.substr(item.find(':') + 1);
            char* end = nullptr;
            weight = std::strtof(w.c_str(), &end);
            if (end == w.c_str() || *end || !(weight >= 0.0f))
                throw UsageError("--light-types '" + text + "': bad weight '" + w + "'");
        }
        if (name == "point") g.pointWeight = weight;
        else if (name == "spot") g.spotWeight = weight;
        else if (name == "directional") g.directionalWeight = weight;
        else throw UsageError("--light-types: unknown type '" + name + "' (point, spot, directional)");
    }
    if (g.pointWeight + g.spotWeight + g.directionalWeight <= 0.0f)
        throw UsageError("--light-types '" + text + "': all weights are zero");
}

} // namespace

void addSceneOptions(CLI::App& app, SceneOptions& o) {
    app.add_option("scene", o.scene,
                   "Scene: a glTF 2.0 file (.gltf/.glb) or builtin:NAME (courtyard, courtyard-small). "
                   "Default: the built-in courtyard");
    app.add_option("--lights", o.lightCount, "Number of generated lights (added to the scene's own)")
        ->capture_default_str();
    app.add_option("--seed", o.seed, "Seed of the light generator: same seed, same lights")->capture_default_str();
    app.add_option("--light-types", o.lightTypes,
                   "Generated light type mix: point, spot, directional with optional weights, "
                   "e.g. point:3,spot:1")
        ->capture_default_str();
    app.add_option("--light-radius", o.lightRadius,
                   "MIN,MAX light range in scene units (default: 4%-12% of the scene's diagonal)");
    app.add_option("--light-intensity", o.lightIntensity,
                   "MIN,MAX intensity in candela (default: derived from the radius)");
    app.add_option("--lights-file", o.lightsFile,
                   "Read lights from this JSON file instead of generating them (see lights.json in any output)");
    app.add_flag("--no-scene-lights", o.dropSceneLights, "Ignore lights defined in the glTF file");
}

void addDeviceOptions(CLI::App& app, DeviceOptions& o) {
    app.add_option("--device", o.device,
                   "Vulkan device by index or name substring (default: a discrete GPU if present, else "
                   "lavapipe); 'triptych info' lists them");
    app.add_flag("--validate", o.validate,
                 "Enable the Khronos validation layers with synchronization validation; any message "
                 "makes the command fail");
}

void addViewOptions(CLI::App& app, ViewOptions& o) {
    app.add_option("--res", o.resolution, "Output resolution WIDTHxHEIGHT")->capture_default_str();
    app.add_option("--msaa", o.msaa, "Samples per pixel: 1, 2, 4 or 8 (as the device supports)")
        ->capture_default_str();
}

Scene loadScene(const SceneOptions& o) {
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
        Result<Scene> s = loadGltf(name, options);
        if (!s) throw UsageError(s.error());
        for (const std::string& w : warnings) std::fprintf(stderr, "triptych: warning: %s\n", w.c_str());
        scene = std::move(*s);
    }
    if (o.dropSceneLights) scene.lights.clear();
    if (!o.lightsFile.empty()) {
        Result<std::vector<Light>> lights = readLightsFile(o.lightsFile);
        if (!lights) throw UsageError(lights.error());
        scene.lights = std::move(*lights);
        return scene;
    }
    if (o.lightCount < 0 || o.lightCount > 1000000)
        throw UsageError("--lights " + std::to_string(o.lightCount) + ": must be between 0 and 1000000");
    LightGenOptions g;
    g.count = uint32_t(o.lightCount);
    g.seed = o.seed;
    parseTypes(o.lightTypes, g);
    if (!o.lightRadius.empty()) std::tie(g.radiusMin, g.radiusMax) = parseRange(o.lightRadius, "--light-radius");
    if (!o.lightIntensity.empty())
        std::tie(g.intensityMin, g.intensityMax) = parseRange(o.lightIntensity, "--light-intensity");
    std::vector<Light> generated = generateLights(scene.bounds, g);
    scene.lights.insert(scene.lights.end(), generated.begin(), generated.end());
    return scene;
}

std::unique_ptr<GpuContext> createContext(const DeviceOptions& o) {
    ContextOptions options;
    options.device = o.device;
    options.validate = o.validate;
    Result<std::unique_ptr<GpuContext>> ctx = GpuContext::create(options);
    if (!ctx) throw UsageError(ctx.error());
    return std::move(*ctx);
}

void addPipelineOptions(CLI::App& app, RenderSettings& s, std::string& referencePrecision) {
    app.add_option("--tile", s.tileSize, "Tile edge in pixels for the tiled pipelines")
        ->check(CLI::IsMember({8u, 16u, 32u}))
        ->capture_default_str();
    app.add_option("--light-lists", s.lightLists,
                   "Forward+ light-list layout: compact (count, prefix sum, fill; never drops), fixed "
                   "(fixed capacity per tile; drops are counted), linked (per-tile linked lists)")
        ->check(CLI::IsMember({"compact", "fixed", "linked"}))
        ->capture_default_str();
    app.add_option("--tile-capacity", s.tileCapacity, "Light slots per tile of the 'fixed' layout")
        ->check(CLI::Range(1u, 65536u))
        ->capture_default_str();
    app.add_option("--gbuffer", s.gbuffer, "Deferred G-buffer layout: compact (8/16-bit) or wide (fp32)")
        ->check(CLI::IsMember({"compact", "wide"}))
        ->capture_default_str();
    app.add_option("--deferred-lighting", s.deferredLighting,
                   "Deferred lighting: tiled (compute, per-tile lists) or volumes (one draw per light)")
        ->check(CLI::IsMember({"tiled", "volumes"}))
        ->capture_default_str();
    app.add_option("--accum", s.accum, "Multipass forward accumulation target precision")
        ->check(CLI::IsMember({"fp16", "fp32"}))
        ->capture_default_str();
    app.add_option("--reference-precision", referencePrecision,
                   "Light-sum accumulation of the reference (fp64 needs shaderFloat64)")
        ->check(CLI::IsMember({"fp32", "fp64"}))
        ->capture_default_str();
}

RenderSettings makeSettings(const ViewOptions& v, const GpuContext& ctx, RenderSettings s) {
    unsigned w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(v.resolution.c_str(), "%u%c%u%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X'))
        throw UsageError("--res '" + v.resolution + "': expected WIDTHxHEIGHT, e.g. 1280x720");
    uint32_t maxDim = ctx.caps.maxImageDimension2D;
    if (w == 0 || h == 0 || w > maxDim || h > maxDim)
        throw UsageError("--res " + v.resolution + ": each side must be between 1 and " +
                         std::to_string(maxDim) + " on " + ctx.info.name);
    if (v.msaa != 1 && v.msaa != 2 && v.msaa != 4 && v.msaa != 8)
        throw UsageError("--msaa " + std::to_string(v.msaa) + ": must be 1, 2, 4 or 8");
    if (!(ctx.caps.colorSampleCounts & uint32_t(v.msaa)))
        throw UsageError("--msaa " + std::to_string(v.msaa) + ": not supported by " + ctx.info.name);
    s.width = w;
    s.height = h;
    s.msaa = uint32_t(v.msaa);
    return s;
}

void ensureDirectory(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
        throw UsageError("--out " + dir + ": cannot create the directory (" + ec.message() + ")");
}

void checkFrameCounts(int frames, int warmup) {
    if (frames < 1 || frames > 10000) throw UsageError("--frames must be between 1 and 10000");
    if (warmup < 0 || warmup > 1000) throw UsageError("--warmup must be between 0 and 1000");
}

float parseExposure(const std::string& text, const ImageRGBA& image) {
    if (text == "auto") return autoExposureEv(image);
    char* end = nullptr;
    float ev = std::strtof(text.c_str(), &end);
    if (end == text.c_str() || *end || !std::isfinite(ev) || std::abs(ev) > 64.0f)
        throw UsageError("--exposure '" + text + "': expected 'auto' or an EV between -64 and 64");
    return ev;
}

RunOptions progressRunOptions(const std::string& label, int warmup, int frames) {
    RunOptions r;
    r.warmupFrames = uint32_t(warmup);
    r.timedFrames = uint32_t(frames);
    const uint32_t w = r.warmupFrames;
    r.onFrame = [label, w](uint32_t f, uint32_t total, double ms) {
        std::fprintf(stderr, "  %s frame %u/%u: %.1f ms%s\n", label.c_str(), f + 1, total, ms,
                     f < w ? " (warm-up)" : "");
    };
    return r;
}

} // namespace tp::cli
