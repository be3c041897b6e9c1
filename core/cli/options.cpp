// The options every command shares (the viewer's `view` among them), and their checks.
#include "core/cli/options.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <CLI/CLI.hpp>

#include "core/cli/shadow_option.h"
#include "core/reference/reference_renderer.h"
#include "core/renderer/renderer.h"
#include "core/renderer/view_settings.h"

namespace tp::cli {

void addSceneOptions(CLI::App& app, SceneOptions& o) {
    app.add_option(
        "scene", o.scene,
        "Scene: a glTF 2.0 file (.gltf/.glb) or builtin:NAME (courtyard, courtyard-small). "
        "Default: the built-in courtyard");
    app.add_option("--lights", o.lightCount,
                   "Number of generated lights (added to the scene's own)")
        ->capture_default_str();
    addSeedOption(app, o.seed);
    app.add_option("--light-types", o.lightTypes,
                   "Generated light type mix: point, spot, directional with optional weights, "
                   "e.g. point:3,spot:1")
        ->capture_default_str();
    app.add_option("--light-radius", o.lightRadius,
                   "MIN,MAX light range in scene units (default: 4%-12% of the scene's diagonal)");
    app.add_option("--light-intensity", o.lightIntensity,
                   "MIN,MAX intensity in candela (default: derived from the radius)");
    app.add_option("--lights-file", o.lightsFile,
                   "Read lights from this JSON file instead of generating them (see lights.json in "
                   "any output)");
    app.add_flag("--no-scene-lights", o.dropSceneLights, "Ignore lights defined in the glTF file");
    addStrictFlag(app, o.strict);
    addCameraOption(app, o.cameraFile);
}

CLI::Option* addCameraOption(CLI::App& app, std::string& path) {
    return app
        .add_option("--camera", path,
                    "Camera bookmark FILE replacing the scene's camera (its glTF camera or the "
                    "built-in one) for this run: "
                    "JSON "
                    "{\"schema\":\"triptych.camera/"
                    "1\",\"position\":[x,y,z],\"target\":[x,y,z],\"up\":[x,y,z],"
                    "\"yfov_degrees\":f,\"znear\":f,\"zfar\":f} (zfar 0: infinite). 'triptych info "
                    "--print-camera' "
                    "writes a scene's camera in this form; render and compare write the camera "
                    "they used as camera.json, and "
                    "report.json, render.json and sweep.json hold it as their \"camera\" object")
        ->type_name("FILE");
}

CLI::Option* addStrictFlag(CLI::App& app, bool& strict) {
    return app.add_flag("--strict", strict,
                        "Refuse a glTF file with NaN or infinite normals, tangents, uvs or colours "
                        "instead of repairing them (repairs are warnings, and listed in the "
                        "report)");
}

CLI::Option* addSeedOption(CLI::App& app, uint64_t& seed) {
    // The check runs on the text: CLI11 would wrap "-1" to 2^64-1.
    return app.add_option("--seed", seed, "Seed of the light generator: same seed, same lights")
        ->check(CLI::Validator(
            [](std::string& text) {
                bool digits = !text.empty() && text.size() <= 20 &&
                              text.find_first_not_of("0123456789") == std::string::npos;
                return digits && (text.size() < 20 || text <= "18446744073709551615")
                           ? std::string()
                           : "'" + text + "' is not a whole number from 0 to 2^64-1";
            },
            "UINT64"))
        ->capture_default_str();
}

void addDeviceOptions(CLI::App& app, DeviceOptions& o) {
    app.add_option(
        "--device", o.device,
        "Vulkan device by index or name substring (default: a discrete GPU if present, else "
        "lavapipe); 'triptych info' lists them");
    app.add_flag(
        "--validate", o.validate,
        "Enable the Khronos validation layers with synchronization validation; any message "
        "makes the command fail");
}

void addViewOptions(CLI::App& app, ViewOptions& o) {
    app.add_option("--res", o.resolution, "Output resolution WIDTHxHEIGHT")->capture_default_str();
    app.add_option("--msaa", o.msaa, "Samples per pixel: 1, 2, 4 or 8 (as the device supports)")
        ->capture_default_str();
    app.add_option("--shadows", o.shadows,
                   "Lights that cast shadows: none, all (every light that reaches the view) or N "
                   "(the N with the largest screen-space influence); point lights get cube maps, "
                   "spots one map, directional lights none (docs/shadows.md)")
        ->capture_default_str();
    app.add_option("--shadow-budget", o.shadowBudgetMb,
                   "Shadow-map memory in MB: each light's map is sized from its screen size, "
                   "the largest halved until the atlas fits (an error if even 16x16 faces do not)")
        ->capture_default_str();
    app.add_option("--shadow-cache", o.shadowCache,
                   "on: the atlas pipelines render their shadow maps once and keep them while the "
                   "shadowed lights do not move (a frame then costs no shadow pass; the one-time "
                   "render is the counter shadow_maps_render_ms); off: every frame renders them "
                   "(pass shadow_maps). One light's map (deferred volumes, multipass) is "
                   "rendered for every light in every frame either way")
        ->check(CLI::IsMember({"on", "off"}))
        ->capture_default_str();
}

CLI::Option* addPassStatisticsOption(CLI::App& app, bool& on) {
    return app
        .add_option("--pass-statistics", on,
                    "on: every pass is bracketed by a pipeline-statistics query (its primitives and "
                    "fragments, which the work counts and the efficiency need); off: none is "
                    "recorded, so the timings do not pay for the queries, and the report says the "
                    "counts and the efficiency were not collected (docs/efficiency.md)")
        ->check(CLI::IsMember({"on", "off"}))
        ->type_name("on|off")
        ->default_str("on");
}

std::unique_ptr<GpuContext> createContext(const DeviceOptions& o) {
    ContextOptions options;
    options.device = o.device;
    options.validate = o.validate;
    Result<std::unique_ptr<GpuContext>> ctx = GpuContext::create(options);
    if (!ctx) throw UsageError(ctx.error());
    return std::move(*ctx);
}

void addKnobOptions(CLI::App& app, std::map<std::string, std::string>& values, bool sweep) {
    for (const KnobReaders& k : allKnobs()) {
        std::string& value = values[k.knob.name]; // a map node: the reference stays valid
        value = k.knob.defaultValue;
        app.add_option("--" + k.knob.name, value, knobHelp(k, sweep && k.knob.sweepable))
            ->capture_default_str();
    }
}

std::string knobHelp(const KnobReaders& k, bool list) {
    std::string readers;
    for (const std::string& r : k.readers)
        readers += (readers.empty() ? "" : ", ") + r;
    return (list ? "Comma-separated values. " : "") + k.knob.help + " [" + k.knob.allowedText() +
           "; read by " + readers + (k.knob.msaaOnly ? "; matters only under MSAA" : "") + "]";
}

void checkKnobs(const std::map<std::string, std::string>& values, bool sweep) {
    for (const KnobReaders& k : allKnobs()) {
        if (sweep && k.knob.sweepable) continue; // a list: runSweep checks each value
        if (Status st = checkSetting(k.knob.name, k.knob.valueIn(values)); !st)
            throw UsageError(st.error());
    }
}

RenderSettings makeSettings(const ViewOptions& v, const GpuContext& ctx, RenderSettings s) {
    uint32_t w = 0, h = 0;
    if (!parseResolution(v.resolution, w, h))
        throw UsageError("--res '" + v.resolution + "': expected WIDTHxHEIGHT, e.g. 1280x720");
    uint32_t maxDim = ctx.caps.maxImageDimension2D;
    if (w == 0 || h == 0 || w > maxDim || h > maxDim)
        throw UsageError("--res " + v.resolution + ": each side must be between 1 and " +
                         std::to_string(maxDim) + " on " + ctx.info.name);
    if (Status ok = checkSetting(kMsaaSetting, std::to_string(v.msaa)); !ok)
        throw UsageError(ok.error());
    if (Status ok = checkSampleCount(ctx, uint32_t(v.msaa)); !ok) throw UsageError(ok.error());
    s.width = w;
    s.height = h;
    s.msaa = uint32_t(v.msaa);
    s.shadows = parseShadowCount(v.shadows);
    if (v.shadowBudgetMb < 1 || v.shadowBudgetMb > 65536)
        throw UsageError("--shadow-budget " + std::to_string(v.shadowBudgetMb) +
                         ": expected 1..65536 MB");
    s.shadows.budgetMb = uint32_t(v.shadowBudgetMb);
    s.shadows.cache = v.shadowCache == "on";
    return s;
}

void ensureDirectory(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
        throw UsageError("--out " + dir + ": cannot create the directory (" + ec.message() + ")");
}

std::string defaultPipelineList() {
    std::string names;
    for (const std::string& n : selectPipelines(""))
        names += (names.empty() ? "" : ",") + n;
    return names;
}

std::vector<std::string> selectPipelines(const std::string& list) {
    std::vector<std::string> names;
    if (list.empty()) {
        for (const RendererEntry& e : registeredRenderers())
            if (e.name != kReferenceRenderer) names.push_back(e.name);
        return names;
    }
    std::stringstream ss(list);
    std::string name;
    while (std::getline(ss, name, ',')) {
        if (name == kReferenceRenderer)
            throw UsageError("--pipelines: the reference is always rendered; list the others");
        Result<const RendererEntry*> e = findRenderer(name);
        if (!e) throw UsageError("--pipelines: " + e.error());
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    if (names.empty()) throw UsageError("--pipelines '" + list + "': no pipeline named");
    return names;
}

int validationExit(const std::vector<std::string>& messages) {
    if (messages.empty()) return 0;
    std::fprintf(stderr, "triptych: %zu validation messages; first: %s\n", messages.size(),
                 messages.front().c_str());
    return 3;
}

} // namespace tp::cli
