#include "compare/report/run_json.h"

#include <cmath>
#include <cstdio>

#include "compare/report/efficiency_json.h"
#include "core/energy/energy_json.h"
#include "core/energy/energy_window.h"
#include "core/renderer/renderer.h"

namespace tp::cli {
namespace {

// An integer knob as a number, the others as text.
nlohmann::json knobJson(const Knob& k, const std::string& value) {
    const bool number = k.kind == Knob::Kind::Integer && k.check(value);
    return number ? nlohmann::json(std::stoull(value)) : nlohmann::json(value);
}

} // namespace

nlohmann::json deviceJson(const GpuContext& ctx) {
    nlohmann::json j;
    j["name"] = ctx.info.name;
    j["type"] = ctx.info.type;
    j["driver"] = ctx.info.driver;
    j["timestamp_period_ns"] = ctx.caps.timestampPeriodNs;
    j["timestamp_valid_bits"] = ctx.caps.timestampValidBits;
    if (ctx.isCpuDevice())
        j["note"] = "CPU device (lavapipe): timings are CPU-rasterizer timings, not GPU timings";
    return j;
}

nlohmann::json settingsJson(const RenderSettings& s) {
    nlohmann::json j = {{"width", s.width},
                        {"height", s.height},
                        {"msaa", s.msaa},
                        {"pass_statistics", s.passStatistics ? "on" : "off"}};
    // Every registered knob by its key, as the run had it (a knob nobody set: its default).
    for (const KnobReaders& k : allKnobs()) {
        j[k.knob.key()] = knobJson(k.knob, k.knob.valueIn(s.knobs));
    }
    return j;
}

nlohmann::json sceneJson(const Scene& scene, const SceneFeatures& f) {
    nlohmann::json repairs = nlohmann::json::array();
    for (const SceneRepair& r : scene.repairs)
        repairs.push_back({{"attribute", r.attribute},
                           {"accessor", r.accessor},
                           {"count", r.count},
                           {"total", r.total},
                           {"problem", r.problem},
                           {"action", r.action}});
    return {{"source", scene.source},
            {"repairs", repairs},
            {"extensions", scene.extensions},
            {"meshes", scene.meshes.size()},
            {"triangles", scene.triangleCount()},
            {"vertices", scene.vertexCount()},
            {"materials", scene.materials.size()},
            {"textures", scene.textures.size()},
            {"lights", scene.lights.size()},
            {"features",
             {{"blended", f.blended},
              {"masked", f.masked},
              {"normal_maps", f.normalMaps},
              {"emissive", f.emissive},
              {"textures", f.textures},
              {"vertex_colors", f.vertexColors},
              {"point_lights", f.pointLights},
              {"spot_lights", f.spotLights},
              {"directional_lights", f.directionalLights}}}};
}

nlohmann::json cameraSourceJson(const CameraSource& s) {
    nlohmann::json j = {{"kind", s.kind}};
    if (s.kind == "gltf") {
        j["gltf_camera"] = s.gltfCamera;
        j["description"] = "the glTF file's camera " + std::to_string(s.gltfCamera) +
                           " (its first perspective camera "
                           "on a drawn node)";
    } else if (s.kind == "file") {
        j["path"] = s.path;
        j["description"] = "--camera " + s.path;
    } else if (s.kind == "framed") {
        j["description"] = "framed from the scene's bounds: the glTF file has no perspective "
                           "camera on a drawn node";
    } else {
        j["description"] = "the built-in scene's camera";
    }
    return j;
}

nlohmann::json runJson(const RunResult& run, const GpuContext& ctx) {
    nlohmann::json j;
    j["pipeline"] = run.renderer;
    j["knobs"] = nlohmann::json::object(); // the knobs this pipeline reads, as it ran
    for (const auto& [knob, value] : run.knobs)
        j["knobs"][knob.key()] = knobJson(knob, value);
    // The shading rate it ran (docs/shading.md): "pixel" or "sample" under MSAA for a
    // pipeline with the msaa-shading knob, "1x" without MSAA.
    for (const auto& [knob, value] : run.knobs)
        if (knob.name == "msaa-shading")
            j["msaa_shading"] = run.msaa > 1 ? value : std::string("1x");
    nlohmann::json timings = nlohmann::json::array();
    for (const TimingStats& t : run.timings)
        timings.push_back({{"pass", t.name},
                           {"median_ms", t.medianMs},
                           {"min_ms", t.minMs},
                           {"max_ms", t.maxMs},
                           {"frames", t.frames},
                           {"device", ctx.info.name}});
    j["timings"] = timings;
    j["energy"] = energyJson(run.energy);
    j["pass_statistics"] = run.statisticsCollected
                               ? nlohmann::json{{"collected", true}}
                               : nlohmann::json{{"collected", false}, {"reason", run.statisticsWhy}};
    j["memory"] = ledgerJson(run.memory);
    const double pixels = double(run.hdr.pixelCount());
    j["memory"]["bytes_per_pixel"] =
        pixels > 0 ? double(j["memory"]["total_bytes"].get<uint64_t>()) / pixels : 0.0;
    nlohmann::json counters = nlohmann::json::object();
    for (const auto& [k, v] : run.stats.counters)
        counters[k] = v;
    j["counters"] = counters;
    nlohmann::json leftOut = nlohmann::json::array();
    for (const LeftOut& l : run.stats.leftOut)
        leftOut.push_back({{"what", l.what}, {"why", l.why}});
    j["left_out"] = leftOut;
    j["passes"] = run.passes;
    j["culled_passes"] = run.culledPasses;
    // Without the statistics a pass's fragment-based counts would read as zeros: left out.
    j["work"] = run.statisticsCollected ? passWorkJson(run.work) : nlohmann::json(nullptr);
    if (run.efficiency) j["efficiency"] = efficiencyJson(*run.efficiency);
    return j;
}

nlohmann::json energySourceJson(const EnergySource& source) {
    if (!source.meter) return {{"available", false}, {"reason", source.why}};
    const EnergyMeter& m = *source.meter;
    return {{"available", true},
            {"source", m.source()},
            {"device", m.device()},
            {"update_period_ms", m.updatePeriodMs()},
            {"min_window_ms", kPeriodsPerWindow * m.updatePeriodMs()}};
}

void noteEnergyLeftOut(const EnergySource& source) {
    if (!source.meter) std::fprintf(stderr, "triptych: energy left out: %s\n", source.why.c_str());
}

nlohmann::json ledgerJson(const std::vector<LedgerEntry>& entries) {
    nlohmann::json memory = nlohmann::json::array();
    uint64_t total = 0;
    for (const LedgerEntry& e : entries) {
        memory.push_back({{"name", e.tag.name},
                          {"pass", e.tag.pass},
                          {"purpose", e.tag.purpose},
                          {"kind", e.isImage ? "image" : "buffer"},
                          {"format", formatName(e.format)},
                          {"width", e.width},
                          {"height", e.height},
                          {"samples", e.samples},
                          {"requested_bytes", e.requestedBytes},
                          {"bytes", e.bytes}});
        total += e.bytes;
    }
    return {{"resources", memory}, {"total_bytes", total}};
}

nlohmann::json metricsJson(const ErrorReport& e) {
    nlohmann::json j;
    for (const MetricInfo& m : metricTable()) {
        double v = m.value(e);
        if (std::isfinite(v))
            j[m.name] = v;
        else
            j[m.name] = nullptr; // JSON has no infinity: PSNR of identical images
    }
    j["max_abs_x"] = e.maxAbsX;
    j["max_abs_y"] = e.maxAbsY;
    j["worst_pixel_x"] = e.worstPixelX;
    j["worst_pixel_y"] = e.worstPixelY;
    j["compared_pixels"] = e.comparedPixels;
    return j;
}

} // namespace tp::cli
