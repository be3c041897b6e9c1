// sweep.csv, sweep.json and sweep.html from the rows of a sweep (docs/report.md describes
// every column and field).
#include "compare/report/sweep_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "compare/report/run_json.h"
#include "compare/report/svg_plot.h"
#include "core/reference/reference_renderer.h"
#include "core/renderer/renderer.h"

namespace tp::cli {
namespace {

std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s)
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string number(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

// RMSE, PSNR and max |difference|; empty when there is no reference to compare with.
std::string errorFields(bool measured, const ErrorReport& e) {
    if (!measured) return ",,";
    return number(e.rmse) + "," + number(e.psnr) + "," + number(e.maxAbs);
}

// Mean HDR-FLIP and mean FLIP of the tonemapped images; empty when not measured.
std::string flipFields(const SweepRow& r) {
    if (!r.measured || !r.flip.measured) return ",";
    return number(r.flip.hdr.mean) + "," + number(r.flip.ldr.mean);
}

// The frame's passes at their ceilings, and its slowest pass's binding ceiling; empty without a
// calibration.
std::string efficiencyFields(const SweepRow& r) {
    if (!r.efficiency || r.efficiency->passes.empty()) return ",,,,";
    const FrameEfficiency& f = *r.efficiency;
    const PassEfficiency& slowest = *std::max_element(
        f.passes.begin(), f.passes.end(),
        [](const PassEfficiency& a, const PassEfficiency& b) { return a.measuredMs < b.measuredMs; });
    return number(f.boundSumMs) + "," + number(f.percent) + "," + csvField(slowest.pass) + "," +
           csvField(slowest.bound.ceiling) + "," + number(slowest.percent);
}

} // namespace

// A row's path columns: empty where the row ran no path (the reference, a failed run).
static std::string pathFields(const nlohmann::json& path) {
    if (path.is_null() || path["summary"]["frame_ms"].is_null()) return ",,,,,,";
    const nlohmann::json& f = path["summary"]["frame_ms"];
    const nlohmann::json& u = path["summary"]["view_update_ms"];
    return std::to_string(path["frame_ms"].size()) + "," + number(f["median"]) + "," +
           number(f["p95"]) + "," + number(f["p99"]) + "," + number(f["max"]) + "," +
           number(u["median"]) + "," + std::to_string(path["replans"].get<uint32_t>());
}

std::string sweepCsv(const std::vector<SweepRow>& rows, const std::string& device) {
    // One column per sweepable knob of the registered pipelines (their key), in registration order.
    std::vector<Knob> columns;
    for (const KnobReaders& k : allKnobs())
        if (k.knob.sweepable) columns.push_back(k.knob);
    std::string t = "pipeline,lights,width,height,msaa,";
    for (const Knob& k : columns)
        t += k.key() + ",";
    t += "status,frame_median_ms,frame_min_ms,frame_max_ms,joules_per_frame,memory_bytes,bytes_per_pixel,rmse_hdr,"
         "psnr_hdr,"
         "max_abs_hdr,rmse_tonemapped,psnr_tonemapped,max_abs_tonemapped,flip_hdr_mean,flip_"
         "tonemapped_mean,"
         "rmse_hdr_center,psnr_hdr_center,max_abs_hdr_center,rmse_tonemapped_center,psnr_"
         "tonemapped_center,"
         "max_abs_tonemapped_center,lights_dropped,ceiling_sum_ms,ceiling_percent,slowest_pass,"
         "slowest_pass_ceiling,slowest_pass_ceiling_percent,";
    // With --camera-path: the path's frame-time percentiles (sweep.json has every view).
    const bool paths = std::any_of(rows.begin(), rows.end(),
                                   [](const SweepRow& r) { return !r.path.is_null(); });
    if (paths)
        t += "path_views,path_frame_median_ms,path_frame_p95_ms,path_frame_p99_ms,"
             "path_frame_max_ms,path_view_update_median_ms,path_replans,";
    t += "device,error\n";
    for (const SweepRow& r : rows) {
        t += csvField(r.pipeline) + "," + std::to_string(r.lights) + "," +
             std::to_string(r.s.width) + "," + std::to_string(r.s.height) + "," +
             std::to_string(r.s.msaa) + ",";
        for (const Knob& k : columns)
            t += csvField(k.valueIn(r.s.knobs)) + ",";
        t += r.status + "," + number(r.frame.medianMs) + "," + number(r.frame.minMs) + "," +
             number(r.frame.maxMs) + "," +
             (r.energy.joulesPerFrame ? number(*r.energy.joulesPerFrame) : std::string()) + "," +
             std::to_string(r.bytes) + "," + number(r.bytesPerPixel) +
             "," + errorFields(r.measured, r.hdr) + "," + errorFields(r.measured, r.display) + "," +
             flipFields(r) + "," + errorFields(r.measuredCenter, r.hdrCenter) + "," +
             errorFields(r.measuredCenter, r.displayCenter) + "," + number(r.dropped) + "," +
             efficiencyFields(r) + "," + (paths ? pathFields(r.path) + "," : std::string()) +
             csvField(device) + "," + csvField(r.error) + "\n";
    }
    return t;
}

nlohmann::json sweepJson(nlohmann::json header, const std::vector<SweepRow>& rows) {
    nlohmann::json runs = nlohmann::json::array();
    for (const SweepRow& r : rows) {
        nlohmann::json j = {{"pipeline", r.pipeline},
                            {"lights", r.lights},
                            {"lights_hash_fnv1a64", r.lightsHash},
                            {"settings", settingsJson(r.s)},
                            {"status", r.status},
                            {"wall_seconds", r.seconds},
                            {"run_index", r.runIndex}};
        if (!r.referenceCache.is_null()) j["reference_cache"] = r.referenceCache;
        if (!r.path.is_null()) j["path"] = r.path;
        if (r.status != "ok")
            j["error"] = r.error;
        else {
            j["run"] = r.run;
            j["lights_dropped"] = r.dropped;
        }
        if (r.measured)
            j["error_vs_reference"] = {{"hdr", metricsJson(r.hdr)},
                                       {"tonemapped", metricsJson(r.display)},
                                       {"flip", flipJson(r.flip)},
                                       {"exposure_ev", r.exposureEv},
                                       {"psnr_peak_hdr", r.hdrPsnrPeak}};
        else
            j["error_vs_reference"] = nullptr;
        if (r.measuredCenter)
            j["error_vs_center_reference"] = {{"hdr", metricsJson(r.hdrCenter)},
                                              {"tonemapped", metricsJson(r.displayCenter)}};
        runs.push_back(std::move(j));
    }
    header["runs"] = std::move(runs);
    return header;
}

namespace {

// The axes a sweep varied among its runs that ran: MSAA, resolution, and per pipeline each
// knob with more than one value there.
struct VariedAxes {
    bool msaa = false, res = false;
    std::map<std::string, std::set<std::string>> knobs; // pipeline -> varied knob names
};

VariedAxes variedAxes(const std::vector<SweepRow>& rows) {
    VariedAxes v;
    std::set<uint32_t> msaa;
    std::set<std::string> res;
    std::map<std::string, std::map<std::string, std::set<std::string>>> values;
    for (const SweepRow& r : rows) {
        if (r.status != "ok") continue;
        msaa.insert(r.s.msaa);
        res.insert(std::to_string(r.s.width) + "x" + std::to_string(r.s.height));
        for (const auto& [name, value] : r.s.knobs)
            values[r.pipeline][name].insert(value);
    }
    v.msaa = msaa.size() > 1;
    v.res = res.size() > 1;
    for (const auto& [pipeline, knobs] : values)
        for (const auto& [name, set] : knobs)
            if (set.size() > 1) v.knobs[pipeline].insert(name);
    return v;
}

// A run's series in the plots: its pipeline and its value of every varied axis, so every run
// is drawn and runs that differ only in what the sweep held fixed share a line.
std::string seriesLabel(const SweepRow& r, const VariedAxes& v) {
    std::string label = r.pipeline;
    if (v.msaa) label += " " + std::to_string(r.s.msaa) + "x";
    if (v.res) label += " " + std::to_string(r.s.width) + "x" + std::to_string(r.s.height);
    if (const auto it = v.knobs.find(r.pipeline); it != v.knobs.end())
        for (const std::string& name : it->second)
            if (const auto k = r.s.knobs.find(name); k != r.s.knobs.end())
                label += " " + name + "=" + k->second;
    return label;
}

// A plot, or the reason it has nothing to draw.
std::string plotOrWhy(const std::vector<PlotPoint>& points, const std::string& why,
                      const std::string& svg) {
    return points.empty() ? "<p><i>" + escapeXml(why) + "</i></p>" : svg;
}

// The sweep page's points: every run that ran in its series, the series' labels and colours,
// and whether the sweep had a reference at all.
struct SweepPlots {
    std::vector<std::string> labels;
    std::vector<int> colours; // per series: its pipeline's, as on every page
    std::vector<PlotPoint> time, memory, error, flipError, centerError;
    bool anyReference = false;
};

SweepPlots collectPlots(const std::vector<SweepRow>& rows) {
    const VariedAxes varied = variedAxes(rows);
    SweepPlots p;
    auto series = [&](const SweepRow& r) {
        const std::string l = seriesLabel(r, varied);
        auto it = std::find(p.labels.begin(), p.labels.end(), l);
        if (it != p.labels.end()) return int(it - p.labels.begin());
        p.labels.push_back(l);
        p.colours.push_back(pipelineColour(r.pipeline));
        return int(p.labels.size() - 1);
    };
    for (const SweepRow& r : rows) {
        p.anyReference = p.anyReference || r.pipeline == kReferenceRenderer;
        if (r.status != "ok") continue;
        const int si = series(r);
        p.time.push_back({"", double(r.lights), r.frame.medianMs, si});
        p.memory.push_back({"", double(r.s.msaa), double(r.bytes) / 1e6, si});
        if (r.measured) p.error.push_back({"", r.frame.medianMs, r.hdr.rmse, si});
        if (r.measured && r.flip.measured)
            p.flipError.push_back({"", r.frame.medianMs, r.flip.hdr.mean, si});
        if (r.measuredCenter)
            p.centerError.push_back({"", r.frame.medianMs, r.hdrCenter.rmse, si});
    }
    return p;
}

} // namespace

std::string sweepHtml(const std::vector<SweepRow>& rows, const std::string& device,
                      const std::string& command) {
    SweepPlots plots = collectPlots(rows);
    const std::vector<std::string>& labels = plots.labels;
    const std::vector<int>& colours = plots.colours;
    std::vector<PlotPoint>&time = plots.time, &memory = plots.memory, &error = plots.error,
                         &flipError = plots.flipError, &centerError = plots.centerError;
    const bool anyReference = plots.anyReference;
    const std::string noError = anyReference
                                    ? "No error figures: the reference failed in every view (see "
                                      "the failed runs above)."
                                    : "No error figures: this sweep ran without a reference "
                                      "(--reference-frames 0).";
    // Pareto front: no other run is both faster and closer to the reference.
    for (std::vector<PlotPoint>* points : {&error, &flipError, &centerError})
        for (PlotPoint& p : *points) {
            p.ring = std::none_of(points->begin(), points->end(), [&](const PlotPoint& q) {
                return q.x <= p.x && q.y <= p.y && (q.x < p.x || q.y < p.y);
            });
        }
    std::string failed;
    for (const SweepRow& r : rows)
        if (r.status != "ok")
            failed += "<li>" +
                      escapeXml(r.pipeline + " (" + std::to_string(r.lights) + " lights, " +
                                std::to_string(r.s.width) + "x" + std::to_string(r.s.height) +
                                ", " + std::to_string(r.s.msaa) + "x MSAA): " + r.error) +
                      "</li>";
    return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>triptych "
           "sweep</title><style>"
           "body{font-family:sans-serif;margin:16px 24px}h2{font-size:18px;border-bottom:1px solid "
           "#ccc}"
           "</style></head><body><h1>triptych sweep</h1><p>Device: <b>" +
           escapeXml(device) + "</b>. Command: <code>" + escapeXml(command) +
           "</code>. Every run is a row of sweep.csv and an entry of sweep.json (every pass, the "
           "memory ledger, "
           "every metric).</p>" +
           (failed.empty() ? "" : "<h2>Failed runs</h2><ul>" + failed + "</ul>") +
           "<h2>Frame time against light count</h2><p>Every run that ran: one line per pipeline "
           "and value of each axis the sweep varied.</p>" +
           plotOrWhy(time, "No run succeeded.",
                     scatterLogLogSvg(time, "lights", "frame median ms", 720, 440, labels,
                                      true, colours)) +
           "<h2>Memory against MSAA</h2>" +
           plotOrWhy(memory, "No run succeeded.",
                     scatterLogLogSvg(memory, "MSAA samples", "pipeline memory (MB)", 720, 440,
                                      labels, false, colours)) +
           "<h2>Error against run time (circled: Pareto front)</h2>" +
           plotOrWhy(error, noError,
                     scatterLogLogSvg(error, "frame median ms", "RMSE vs reference (HDR)", 720,
                                      440, labels, false, colours)) +
           "<h2>Perceived error against run time: HDR-FLIP (circled: Pareto front)</h2>" +
           plotOrWhy(flipError, noError,
                     scatterLogLogSvg(flipError, "frame median ms", "mean HDR-FLIP vs reference",
                                      720, 440, labels, false, colours)) +
           // Under MSAA: the error with the shading rate left out (docs/report.md, two errors under
           // MSAA).
           (centerError.empty()
                ? ""
                : "<h2>Method error against run time: against the centre reference, MSAA runs "
                  "(circled: Pareto "
                  "front)</h2>" +
                      scatterLogLogSvg(centerError, "frame median ms",
                                       "RMSE vs centre reference (HDR)", 720, 440, labels, false,
                                       colours)) +
           "</body></html>\n";
}

} // namespace tp::cli
