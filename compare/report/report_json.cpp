// report.json: everything needed to read the comparison and to repeat it (command line,
// seed, scene path and hash, settings, device). Field meanings: docs/report.md.
#include "compare/report/report_json.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "compare/report/run_json.h"
#include "core/camera/camera_file.h"
#include "core/cli/shadow_option.h"

namespace tp::cli {
namespace {

nlohmann::json outcomeJson(const PipelineOutcome& p, const GpuContext& ctx, bool isReference) {
    nlohmann::json j;
    j["name"] = p.name;
    j["status"] = p.run ? "ok" : "failed";
    j["files"] = p.files;
    if (!p.run) {
        j["error"] = p.error;
        return j;
    }
    j["run"] = runJson(*p.run, ctx);
    if (isReference) j["cache"] = referenceCacheJson(p.cache);
    // Pipelines that cannot drop a light do not count drops: 0 for them.
    j["lights_dropped"] = counterValue(*p.run, "lights_dropped");
    if (!isReference) {
        j["error_vs_reference"] = {{"hdr", metricsJson(p.hdr)},
                                   {"tonemapped", metricsJson(p.display)},
                                   {"flip", flipJson(p.flip)}};
        j["difference_p99"] = p.diffP99;
        if (p.hdrVsCenter)
            j["error_vs_center_reference"] = {{"hdr", metricsJson(*p.hdrVsCenter)},
                                              {"tonemapped", metricsJson(*p.displayVsCenter)}};
        if (p.hdrVsShadowMaps)
            j["error_vs_shadow_map_reference"] = {{"hdr", metricsJson(*p.hdrVsShadowMaps)},
                                                  {"tonemapped", metricsJson(*p.displayVsShadowMaps)}};
    }
    return j;
}

// A second reference that ran: its files, its cost, how far it is from the first.
nlohmann::json secondReferenceJson(const CompareRecord& r, const PipelineOutcome& c,
                                   const std::string& knob, const std::string& meaning) {
    if (!c.run) return {{"rendered", false}, {"why", "failed: " + c.error}};
    nlohmann::json j = {{"rendered", true}, {"knob", knob}, {"files", c.files}};
    j["run"] = runJson(*c.run, *r.ctx);
    j["cache"] = referenceCacheJson(c.cache);
    j["error_vs_reference"] = {{"hdr", metricsJson(c.hdr)}, {"tonemapped", metricsJson(c.display)}};
    j["meaning"] = meaning;
    return j;
}

// The second reference under MSAA: whether it ran, what it cost, how far it is from the first.
nlohmann::json centerReferenceJson(const CompareRecord& r) {
    if (r.settings.msaa == 1)
        return {{"rendered", false}, {"why", "MSAA is 1x: both references are one image"}};
    if (!r.request.centerReference) return {{"rendered", false}, {"why", "--no-center-reference"}};
    return secondReferenceJson(
        r, r.centerReference, "reference-msaa center",
        "error against the supersampled reference = total; against the centre reference = the "
        "method alone (the shading rate left out); the centre reference's own error is the cost "
        "of shading once per pixel");
}

// With --shadows: the reference that samples the pipelines' shadow maps.
nlohmann::json shadowMapReferenceJson(const CompareRecord& r) {
    if (!r.settings.shadows.enabled())
        return {{"rendered", false}, {"why", "no shadows (--shadows none)"}};
    if (r.shadowPlan.empty())
        return {{"rendered", false}, {"why", "no shadowed light reaches the view"}};
    return secondReferenceJson(
        r, r.shadowMapReference, "reference-shadows maps",
        "error against the ray-traced reference = total; against the shadow-map reference = the "
        "lighting architecture alone (the same maps, the same filter); the shadow-map "
        "reference's own error is the shadow maps' (resolution, filter, bias)");
}

// --shadows: what was asked, what the plan gave (docs/shadows.md).
nlohmann::json shadowsJson(const CompareRecord& r) {
    const ShadowSettings& s = r.settings.shadows;
    nlohmann::json j = {{"shadows", shadowCountText(s)}, {"budget_mb", s.budgetMb}};
    if (!s.enabled()) return j;
    const ShadowPlan& p = r.shadowPlan;
    std::vector<uint32_t> edges;
    for (const ShadowLight& l : p.lights) edges.push_back(l.edge);
    std::sort(edges.begin(), edges.end());
    j["shadowed_lights"] = p.lights.size();
    j["requested"] = p.requested;
    j["faces"] = p.faces.size();
    j["face_edge_texels"] = edges.empty() ? nlohmann::json() :
        nlohmann::json{{"min", edges.front()}, {"median", edges[edges.size() / 2]}, {"max", edges.back()}};
    j["atlas"] = {{"width", p.atlasWidth}, {"height", p.atlasHeight}, {"bytes", p.atlasBytes()}};
    j["one_light_map"] = {{"width", p.localWidth}, {"height", p.localHeight}, {"bytes", p.localBytes()}};
    j["filter"] = {{"pcf_texels", (2 * TP_SHADOW_PCF_RADIUS + 1) * (2 * TP_SHADOW_PCF_RADIUS + 1)},
                   {"normal_offset_texels", TP_SHADOW_NORMAL_OFFSET},
                   {"depth_bias_texels", TP_SHADOW_DEPTH_BIAS}};
    return j;
}

nlohmann::json metricTableJson(const CompareRecord& r) {
    nlohmann::json list = nlohmann::json::array();
    for (const MetricInfo& m : metricTable())
        list.push_back({{"name", m.name}, {"description", m.description}});
    MetricsOptions defaults;
    return {{"metrics", list},
            {"relative_epsilon", defaults.relativeEpsilon},
            {"over_threshold", defaults.overThreshold},
            {"psnr_peak_hdr", r.hdrPsnrPeak},
            {"psnr_peak_tonemapped", 1.0},
            {"hdr_psnr_peak_rule", "brightest finite RGB channel of the reference image"}};
}

} // namespace

nlohmann::json reportJson(const CompareRecord& r) {
    const CompareRequest& o = r.request;
    nlohmann::json j;
    j["schema"] = "triptych.report/2";
    j["command_line"] = o.commandLine;
    j["command"] = shellJoin(o.commandLine);
    bool allOk = std::all_of(r.pipelines.begin(), r.pipelines.end(),
                             [](const PipelineOutcome& p) { return bool(p.run); });
    j["status"] = allOk ? "ok" : "failed";
    j["seed"] = o.seed;
    j["scene"] = sceneJson(*r.scene, r.features);
    j["scene"]["path"] = o.scenePath.empty() ? "builtin:courtyard" : o.scenePath;
    j["scene"]["hash_fnv1a64"] =
        r.sceneHash.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.sceneHash);
    const bool fromFile = !r.sceneFiles.hash.empty();
    j["scene"]["files_hash_fnv1a64"] =
        fromFile ? nlohmann::json(r.sceneFiles.hash) : nlohmann::json(nullptr);
    j["scene"]["files_hashed"] = r.sceneFiles.files;
    j["scene"]["files_missing"] = r.sceneFiles.missing;
    j["scene"]["content_hash_fnv1a64"] = r.contentHash;
    j["scene"]["lights_hash_fnv1a64"] = r.lightsHash;
    j["scene"]["camera_hash_fnv1a64"] = hashCamera(r.scene->camera);
    j["camera"] =
        cameraToJson(r.scene->camera); // a camera file: `jq .camera report.json` is a --camera FILE
    j["camera_source"] = cameraSourceJson(r.cameraSource);
    j["camera_file"] = "camera.json";
    j["scene"]["lights_file"] = "lights.json";
    j["settings"] = settingsJson(r.settings);
    j["settings"]["frames"] = o.frames;
    j["settings"]["warmup"] = o.warmup;
    j["settings"]["exposure"] = o.exposure;
    j["settings"]["exposure_ev"] = r.exposureEv;
    j["settings"]["light_types"] = o.lightTypes;
    j["settings"]["lights_requested"] = o.lightsRequested;
    j["device"] = deviceJson(*r.ctx);
    j["calibration"] = calibrationUseJson(*r.calibration);
    j["energy_source"] = energySourceJson(*r.energy);
    j["difference_scale"] = {
        {"value", r.diffScale},
        {"unit", "linear radiance, max over RGB of |pipeline - reference|"},
        {"rule", "largest 99th percentile of |difference| over the pipelines"}};
    j["metrics_table"] = metricTableJson(r);
    j["flip"] = flipConditionsJson(o.flipDistance);
    j["shared_memory"] = ledgerJson(r.sharedMemory);
    j["shared_memory"]["owner"] = "scene";
    j["reference"] = outcomeJson(r.reference, *r.ctx, true);
    nlohmann::json pipelines = nlohmann::json::array();
    for (const PipelineOutcome& p : r.pipelines)
        pipelines.push_back(outcomeJson(p, *r.ctx, false));
    j["pipelines"] = pipelines;
    j["center_reference"] = centerReferenceJson(r);
    j["shadow_map_reference"] = shadowMapReferenceJson(r);
    j["shadows"] = shadowsJson(r);
    nlohmann::json pairs = nlohmann::json::array();
    for (const PairOutcome& p : r.pairs)
        pairs.push_back({{"a", p.a},
                         {"b", p.b},
                         {"hdr", metricsJson(p.hdr)},
                         {"tonemapped", metricsJson(p.display)},
                         {"difference_p99", p.diffP99},
                         {"files", p.files}});
    j["pairwise"] = pairs;
    if (!r.path.is_null()) j["path"] = r.path;
    j["validation_messages"] = r.validationMessages;
    j["files"] = {"lights.json", "report.json", "report.html"};
    return j;
}

std::string shellJoin(const std::vector<std::string>& args) {
    std::string out;
    for (const std::string& a : args) {
        if (!out.empty()) out += ' ';
        bool plain =
            !a.empty() && a.find_first_of(" \t\n\"'\\$`;&|<>()*?[]{}#~!") == std::string::npos;
        std::string quoted = "'";
        for (char c : a)
            quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
        out += plain ? a : quoted + "'";
    }
    return out;
}

std::string hashFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    uint64_t h = 1469598103934665603ull; // FNV-1a 64 offset basis
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        for (std::streamsize i = 0; i < in.gcount(); ++i) {
            h ^= uint8_t(buffer[i]);
            h *= 1099511628211ull;
        }
        if (!in) break;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", (unsigned long long)h);
    return hex;
}

} // namespace tp::cli
