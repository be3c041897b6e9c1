// The error half of report.html: the summary table, the two references under MSAA, the
// error-against-time plots and the FLIP section (report_html.cpp assembles the page).
#include <algorithm>
#include <sstream>

#include "compare/report/report_html_parts.h"
#include "core/image/metrics.h"
#include "compare/report/svg_plot.h"

namespace tp::cli::html {

using nlohmann::json;

// A pooled FLIP value of a pipeline, null when FLIP was not measured.
json flipValue(const json& p, const char* kind, const char* key) {
    const json& f = p["error_vs_reference"].value("flip", json(nullptr));
    return f.is_object() ? f[kind][key] : json(nullptr);
}

const char* kFlipExplanation = "FLIP (Andersson et al. 2020) estimates what a viewer flipping "
                               "between the two images would notice, per "
                               "pixel in [0, 1]: both images are filtered by the eye's contrast "
                               "sensitivity at the viewing distance, "
                               "compared in a perceptually uniform colour space, and the "
                               "difference is raised where edges or points differ. "
                               "HDR-FLIP (2021) runs it on the linear images tonemapped at a range "
                               "of exposures chosen from the reference "
                               "and keeps each pixel's worst. Read it next to RMSE: RMSE counts "
                               "every unit of radiance equally, wherever it "
                               "lands, so a bright noisy highlight can dominate it while nobody "
                               "would see it, and a faint banding step on a "
                               "flat wall barely moves it while everybody would. A mean FLIP near "
                               "0 means hard to tell apart; the weighted "
                               "median and quartiles say how large the errors that make up most of "
                               "the total are; the map shows where.";

std::string flipSection(const json& r) {
    const json& c = r.value("flip", json(nullptr));
    if (!c.is_object()) return "";
    std::string h = "<h2>FLIP</h2>\n<p class=\"meta\">" + std::string(kFlipExplanation) +
                    " Viewing distance " + formatNumber(c["viewing_distance_m"].get<double>()) +
                    " m, " + formatNumber(c["pixels_per_degree"].get<double>()) +
                    " pixels per degree (" + esc(c["monitor"]) + "); FLIP (tonemapped) on " +
                    esc(c["ldr_input"]) + ", HDR-FLIP on " + esc(c["hdr_input"]) + ".</p>\n";
    h += "<table><tr><th class=\"l\">pipeline</th><th "
         "class=\"l\">input</th><th>mean</th><th>weighted median</th>"
         "<th>weighted Q1</th><th>weighted Q3</th><th>max</th><th>exposures</th></tr>\n";
    for (const json& p : r["pipelines"]) {
        if (!ok(p) || !flipValue(p, "hdr", "mean").is_number()) continue;
        const json& f = p["error_vs_reference"]["flip"];
        for (const char* kind : {"hdr", "ldr"}) {
            const json& v = f[kind];
            std::string exposures = "&mdash;";
            if (std::string(kind) == "hdr")
                exposures = std::to_string(v["exposures"].get<int>()) + " from " +
                            formatNumber(v["start_exposure"].get<double>()) + " to " +
                            formatNumber(v["stop_exposure"].get<double>()) + " EV";
            h += "<tr><td class=\"l\">" + esc(p["name"]) + "</td><td class=\"l\">" +
                 (std::string(kind) == "hdr" ? "HDR-FLIP (linear)" : "FLIP (tonemapped)") +
                 "</td>" + numberCell(v["mean"]) + numberCell(v["weighted_median"]) +
                 numberCell(v["weighted_q1"]) + numberCell(v["weighted_q3"]) +
                 numberCell(v["max"]) + "<td>" + exposures + "</td></tr>\n";
        }
    }
    return h + "</table>\n";
}

std::string summaryTable(const json& r) {
    std::string device = esc(r["device"]["name"]);
    std::string t =
        "<h2>Summary</h2>\n<table><tr><th class=\"l\">pipeline</th><th>frame median ms<br>(" +
        device +
        ")</th><th>J / frame</th><th>memory MiB</th><th>bytes / pixel</th><th>RMSE (HDR)</th><th>RMSE (HDR) "
        "without the worst pixel</th><th>mean relative error (HDR)</th><th>PSNR dB "
        "(tonemapped)</th><th>share over threshold (tonemapped)</th><th>HDR-FLIP mean</th><th>FLIP "
        "mean "
        "(tonemapped)</th><th>lights dropped</th></tr>\n";
    std::string dominated; // the pipelines whose RMSE one pixel decides
    auto row = [&](const json& p, bool reference) {
        t += "<tr><td class=\"l\">" + esc(p["name"]) + "</td>";
        if (!ok(p)) {
            t += "<td colspan=\"12\" class=\"l\">failed: " + esc(p["error"]) + "</td></tr>\n";
            return;
        }
        const json& mem = p["run"]["memory"];
        t += "<td>" + formatNumber(frameMedian(p)) + "</td>" + joulesCell(p["run"]) + "<td>" +
             formatNumber(mem["total_bytes"].get<double>() / 1048576.0) + "</td>" +
             numberCell(mem["bytes_per_pixel"]);
        if (reference)
            t += "<td>0</td><td>0</td><td>0</td><td>inf</td><td>0</td><td>0</td><td>0</td>";
        else {
            const json& e = p["error_vs_reference"];
            const json& hdr = e["hdr"];
            const double share = hdr.value("worst_pixel_share", 0.0);
            const bool one = share > kOnePixelDominates;
            if (one)
                dominated += "<li>" + esc(p["name"]) + ": pixel (" +
                             std::to_string(hdr.value("worst_pixel_x", 0)) + ", " +
                             std::to_string(hdr.value("worst_pixel_y", 0)) + ") holds " +
                             formatNumber(100.0 * share) + " % of the squared error</li>";
            t += (one ? "<td class=\"warn\">&dagger; " : "<td>") + formatNumber(hdr["rmse"]) +
                 "</td>" + numberCell(hdr["rmse_without_worst_pixel"]) +
                 numberCell(hdr["mean_relative"]) + numberCell(e["tonemapped"]["psnr"]) +
                 numberCell(e["tonemapped"]["share_over_threshold"]) +
                 numberCell(flipValue(p, "hdr", "mean")) + numberCell(flipValue(p, "ldr", "mean"));
        }
        t += numberCell(p["lights_dropped"]) + "</tr>\n";
    };
    row(r["reference"], true);
    for (const json& p : r["pipelines"])
        row(p, false);
    t += "</table>\n";
    if (!dominated.empty())
        t += "<p class=\"meta\">&dagger; One pixel decides this RMSE (it holds more than half of "
             "the squared error): near a light's 1/d&sup2; pole a tiny difference in the shaded "
             "position is a large one in radiance, and one such pixel can rank the pipelines. "
             "Read the RMSE without it and the mean relative error (|p &minus; r| / max(|r|, "
             "10<sup>&minus;3</sup>)), which no single pixel decides.</p><ul>" +
             dominated + "</ul>\n";
    t += "<p class=\"meta\">Shared scene data (counted once, not in any pipeline's "
         "total): " +
         formatNumber(r["shared_memory"]["total_bytes"].get<double>() / 1048576.0) + " MiB.</p>\n";
    return t;
}

// True when the report holds the second error (MSAA, centre reference rendered).
bool hasCenterReference(const json& r) {
    return r.contains("center_reference") && r["center_reference"].value("rendered", false);
}

// `key`: error_vs_reference or error_vs_center_reference; `metric`: its HDR metric plotted.
std::string errorScatter(const json& r, const std::string& key, const std::string& yLabel,
                         const std::string& metric = "rmse") {
    std::vector<PlotPoint> points;
    points.push_back({"reference (error 0)", frameMedian(r["reference"]), 0.0, -1, false,
                      pipelineColour(r["reference"]["name"].get<std::string>())});
    for (const json& p : r["pipelines"])
        if (ok(p) && p.contains(key))
            points.push_back({p["name"].get<std::string>(), frameMedian(p),
                              p[key]["hdr"].value(metric, 0.0), -1, false,
                              pipelineColour(p["name"].get<std::string>())});
    return scatterLogLogSvg(
        points, "frame time, median ms on " + r["device"]["name"].get<std::string>(), yLabel);
}

// Both errors per pipeline: against the first reference and against a second one (`errorKey`),
// after a paragraph that says what separates them.
std::string twoErrorTable(const json& r, const std::string& title, const std::string& intro,
                          const std::string& first, const std::string& second,
                          const std::string& errorKey, bool msaaColumn) {
    std::string t = "<h2>" + title + "</h2>\n<p class=\"meta\">" + intro + "</p>\n"
                    "<table><tr><th class=\"l\">pipeline</th>" +
                    (msaaColumn ? "<th class=\"l\">MSAA shading</th>" : "") +
                    "<th>RMSE (HDR) vs " + first + "</th><th>RMSE (HDR) vs " + second +
                    "</th><th>PSNR dB (tonemapped) vs " + first + "</th><th>PSNR dB (tonemapped) vs " +
                    second + "</th></tr>\n";
    for (const json& p : r["pipelines"]) {
        if (!ok(p) || !p.contains(errorKey)) continue;
        const json &a = p["error_vs_reference"], &b = p[errorKey];
        t += "<tr><td class=\"l\">" + esc(p["name"]) + "</td>";
        if (msaaColumn)
            t += "<td class=\"l\">" +
                 (p["run"].contains("msaa_shading") ? esc(p["run"]["msaa_shading"])
                                                    : std::string("&ndash;")) + "</td>";
        t += numberCell(a["hdr"]["rmse"]) + numberCell(b["hdr"]["rmse"]) +
             numberCell(a["tonemapped"]["psnr"]) + numberCell(b["tonemapped"]["psnr"]) + "</tr>\n";
    }
    return t + "</table>\n";
}

// Under MSAA with the centre reference.
std::string twoReferences(const json& r) {
    const json& c = r["center_reference"];
    return twoErrorTable(
        r, "Two errors under MSAA",
        "Against the supersampled reference the error is the total; against the centre reference "
        "(<code>--reference-msaa center</code>: every sample shaded at the pixel centre) it is the "
        "method alone, because the shading rate is left out: their difference is what shading "
        "once per pixel costs. The centre reference itself is RMSE " +
            formatNumber(c["error_vs_reference"]["hdr"]["rmse"].get<double>()) +
            " from the supersampled one; it cost one more reference render (frame median " +
            formatNumber(frameMedian(c)) + " ms; <code>--no-center-reference</code> skips it).",
        "supersampled: total", "centre: method", "error_vs_center_reference", true);
}

bool hasShadowMapReference(const json& r) {
    return r.contains("shadow_map_reference") && r["shadow_map_reference"].value("rendered", false);
}

// With --shadows: against the ray-traced reference and against the one that samples the maps.
std::string shadowReferences(const json& r) {
    const json& c = r["shadow_map_reference"];
    const json& s = r["shadows"];
    return twoErrorTable(
        r, "Two errors with shadows",
        "The reference casts a shadow ray per sample and shadowed light (exact visibility); the "
        "shadow-map reference shades every light at every sample as well, but takes visibility "
        "from the shadow maps the pipelines render, with their filter (" +
            std::to_string(s["filter"]["pcf_texels"].get<int>()) +
            "-texel PCF). Against the first a pipeline's error is the total; against the second, "
            "its lighting architecture's part alone; the shadow maps' own part is the shadow-map "
            "reference's error, RMSE " +
            formatNumber(c["error_vs_reference"]["hdr"]["rmse"].get<double>()) + ". " +
            std::to_string(s["shadowed_lights"].get<int>()) + " lights cast shadows (" +
            std::to_string(s["faces"].get<int>()) + " faces; atlas " +
            formatNumber(s["atlas"]["bytes"].get<double>() / 1048576.0) + " MiB, one light's map " +
            formatNumber(s["one_light_map"]["bytes"].get<double>() / 1048576.0) + " MiB).",
        "rays: total", "maps: architecture", "error_vs_shadow_map_reference", false);
}

// Mean HDR-FLIP against frame time: what a viewer would see, beside the RMSE plots.
std::string flipScatter(const json& r) {
    std::vector<PlotPoint> points;
    points.push_back({"reference (error 0)", frameMedian(r["reference"]), 0.0, -1, false,
                      pipelineColour(r["reference"]["name"].get<std::string>())});
    for (const json& p : r["pipelines"])
        if (ok(p) && flipValue(p, "hdr", "mean").is_number())
            points.push_back({p["name"].get<std::string>(), frameMedian(p),
                              flipValue(p, "hdr", "mean").get<double>(), -1, false,
                              pipelineColour(p["name"].get<std::string>())});
    if (points.size() < 2) return "";
    return scatterLogLogSvg(points,
                            "frame time, median ms on " + r["device"]["name"].get<std::string>(),
                            "mean HDR-FLIP vs reference");
}

std::string errorPlot(const json& r) {
    const std::string note =
        "<p class=\"meta\">Lower left is better: cheaper and closer to the reference (by "
        "RMSE, by the mean relative error, which one hot pixel cannot decide, and by what a "
        "viewer would see: HDR-FLIP).</p>\n";
    if (!hasCenterReference(r))
        return "<h2>Error against run time</h2>\n" +
               errorScatter(r, "error_vs_reference", "RMSE vs reference (linear HDR)") +
               errorScatter(r, "error_vs_reference",
                            "mean relative error vs reference (linear HDR; no pixel decides it)",
                            "mean_relative") +
               flipScatter(r) + note;
    return "<h2>Error against run "
           "time</h2>\n<style>#ep-c:checked~.ep-s,#ep-s:checked~.ep-c{display:none}</style>"
           "<input type=\"radio\" name=\"ep\" id=\"ep-s\" checked><label for=\"ep-s\">against the "
           "supersampled "
           "reference (total)</label> <input type=\"radio\" name=\"ep\" id=\"ep-c\"><label "
           "for=\"ep-c\">against "
           "the centre reference (method alone)</label>\n<div class=\"ep-s\">" +
           errorScatter(r, "error_vs_reference", "RMSE vs supersampled reference (linear HDR)") +
           "</div><div class=\"ep-c\">" +
           errorScatter(r, "error_vs_center_reference", "RMSE vs centre reference (linear HDR)") +
           "</div>\n" + flipScatter(r) + note;
}

} // namespace tp::cli::html
