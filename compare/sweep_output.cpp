// sweep.csv, sweep.json and sweep.html from the rows of a sweep (docs/report.md describes
// every column and field).
#include "compare/sweep_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "compare/run_json.h"
#include "compare/svg_plot.h"
#include "core/render/renderer.h"

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

} // namespace

std::string sweepCsv(const std::vector<SweepRow>& rows, const std::string& device) {
    // One column per sweepable knob of the registered pipelines (their key), in registration order.
    std::vector<Knob> columns;
    for (const KnobReaders& k : allKnobs())
        if (k.knob.sweepable) columns.push_back(k.knob);
    std::string t = "pipeline,lights,width,height,msaa,";
    for (const Knob& k : columns)
        t += k.key() + ",";
    t += "status,frame_median_ms,frame_min_ms,frame_max_ms,memory_bytes,bytes_per_pixel,rmse_hdr,"
         "psnr_hdr,"
         "max_abs_hdr,rmse_tonemapped,psnr_tonemapped,max_abs_tonemapped,flip_hdr_mean,flip_"
         "tonemapped_mean,"
         "rmse_hdr_center,psnr_hdr_center,max_abs_hdr_center,rmse_tonemapped_center,psnr_"
         "tonemapped_center,"
         "max_abs_tonemapped_center,lights_dropped,device,error\n";
    for (const SweepRow& r : rows) {
        t += csvField(r.pipeline) + "," + std::to_string(r.lights) + "," +
             std::to_string(r.s.width) + "," + std::to_string(r.s.height) + "," +
             std::to_string(r.s.msaa) + ",";
        for (const Knob& k : columns)
            t += csvField(k.valueIn(r.s.knobs)) + ",";
        t += r.status + "," + number(r.frame.medianMs) + "," + number(r.frame.minMs) + "," +
             number(r.frame.maxMs) + "," + std::to_string(r.bytes) + "," + number(r.bytesPerPixel) +
             "," + errorFields(r.measured, r.hdr) + "," + errorFields(r.measured, r.display) + "," +
             flipFields(r) + "," + errorFields(r.measuredCenter, r.hdrCenter) + "," +
             errorFields(r.measuredCenter, r.displayCenter) + "," + number(r.dropped) + "," +
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

std::string sweepHtml(const std::vector<SweepRow>& rows, const std::vector<std::string>& names,
                      const std::string& device, const std::string& command) {
    auto series = [&](const std::string& p) {
        return int(std::find(names.begin(), names.end(), p) - names.begin());
    };
    std::vector<PlotPoint> time, memory, error, flipError, centerError;
    std::set<std::string> firstOfKind;
    for (const SweepRow& r : rows) {
        if (r.status != "ok") continue;
        int si = series(r.pipeline);
        // Time against lights: the first resolution, MSAA and knob values only, one line per
        // pipeline.
        if (r.s.width == rows.front().s.width && r.s.msaa == rows.front().s.msaa &&
            firstOfKind.insert(r.pipeline + "/" + std::to_string(r.lights)).second)
            time.push_back({"", double(r.lights), r.frame.medianMs, si});
        memory.push_back({"", double(r.s.msaa), double(r.bytes), si});
        if (r.measured) error.push_back({"", r.frame.medianMs, r.hdr.rmse, si});
        if (r.measured && r.flip.measured)
            flipError.push_back({"", r.frame.medianMs, r.flip.hdr.mean, si});
        if (r.measuredCenter) centerError.push_back({"", r.frame.medianMs, r.hdrCenter.rmse, si});
    }
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
           "<h2>Frame time against light count</h2>" +
           scatterLogLogSvg(time, "lights", "frame median ms", 720, 440, names) +
           "<h2>Memory against MSAA</h2>" +
           scatterLogLogSvg(memory, "MSAA samples", "pipeline bytes", 720, 440, names, false) +
           "<h2>Error against run time (circled: Pareto front)</h2>" +
           scatterLogLogSvg(error, "frame median ms", "RMSE vs reference (HDR)", 720, 440, names,
                            false) +
           "<h2>Perceived error against run time: HDR-FLIP (circled: Pareto front)</h2>" +
           scatterLogLogSvg(flipError, "frame median ms", "mean HDR-FLIP vs reference", 720, 440,
                            names, false) +
           // Under MSAA: the error with the shading rate left out (docs/report.md, two errors under
           // MSAA).
           (centerError.empty()
                ? ""
                : "<h2>Method error against run time: against the centre reference, MSAA runs "
                  "(circled: Pareto "
                  "front)</h2>" +
                      scatterLogLogSvg(centerError, "frame median ms",
                                       "RMSE vs centre reference (HDR)", 720, 440, names, false)) +
           "</body></html>\n";
}

} // namespace tp::cli
