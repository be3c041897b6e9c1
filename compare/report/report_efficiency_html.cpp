// report.html's efficiency section: every pass placed against the device's measured ceilings
// (docs/efficiency.md): a roofline of the passes that evaluate lights, and a table of every
// pass's binding ceiling beside its measured time.
#include <algorithm>
#include <cmath>

#include "compare/report/report_html_parts.h"
#include "compare/report/svg_plot.h"
#include "core/renderer/pipeline_colour.h"

namespace tp::cli::html {
namespace {

using nlohmann::json;

double ceiling(const json& cal, const char* name) { return cal["ceilings"].value(name, 0.0); }

// The roofs: min(ALU ceiling, DRAM read x intensity) over the plotted intensities.
std::vector<PlotLine> roofs(const json& cal, double xlo, double xhi) {
    const double bw = ceiling(cal, "dram_read");
    std::vector<PlotLine> lines;
    for (const auto& [name, dashed] : {std::pair{"fp32_fma", false}, std::pair{"fragment_fma", true}}) {
        const double peak = ceiling(cal, name);
        if (peak <= 0 || bw <= 0) continue;
        PlotLine l{{}, std::string(dashed ? "fragment" : "compute") + " FMA " + formatNumber(peak) + " GFLOP/s", dashed};
        const double knee = peak / bw;
        l.xy.push_back({xlo, std::min(peak, bw * xlo)});
        if (knee > xlo && knee < xhi) l.xy.push_back({knee, peak});
        l.xy.push_back({xhi, std::min(peak, bw * xhi)});
        lines.push_back(l);
    }
    return lines;
}

std::string rooflineSvg(const json& r) {
    std::vector<PlotPoint> points;
    std::vector<std::string> names;
    std::vector<int> colours;
    for (const json& p : r["pipelines"]) {
        if (!ok(p) || !p["run"].contains("efficiency")) continue;
        const int series = int(names.size());
        for (const json& e : p["run"]["efficiency"]["passes"])
            if (e.contains("roofline"))
                points.push_back({e["pass"].get<std::string>(), e["roofline"]["intensity_flops_per_byte"].get<double>(),
                                  e["roofline"]["achieved_gflops"].get<double>(), series});
        names.push_back(p["name"].get<std::string>());
        colours.push_back(pipelineColour(names.back()));
    }
    if (points.empty()) return "<p>No pass evaluated lights with work counted: no roofline.</p>\n";
    double xlo = INFINITY, xhi = 0;
    for (const PlotPoint& pt : points)
        if (pt.x > 0) xlo = std::min(xlo, pt.x), xhi = std::max(xhi, pt.x);
    if (!(xhi > 0)) xlo = 1e-3, xhi = 1e3; // every point without bytes: a range around them
    return scatterLogLogSvg(points, "light evaluations as FLOPs per byte moved", "achieved GFLOP/s", 760, 460,
                            names, false, colours, roofs(r["calibration"], xlo / 4, xhi * 4));
}

std::string limitCell(const json& e) {
    if (e["bound"].is_null()) return "<td class=\"l\">(no counted work)</td><td></td><td></td>";
    return "<td class=\"l\">" + esc(e["bound"]["limit"]) + " (" + esc(e["bound"]["ceiling"]) + ")</td>" +
           numberCell(e["bound"]["ms"]) + numberCell(e["percent_of_ceiling"]);
}

std::string passTable(const json& r) {
    std::string h = "<table><tr><th class=\"l\">pipeline</th><th class=\"l\">pass</th><th>measured ms</th>"
                    "<th class=\"l\">binding ceiling</th><th>ms at it</th><th>% of it</th></tr>\n";
    for (const json& p : r["pipelines"]) {
        if (!ok(p) || !p["run"].contains("efficiency")) continue;
        const json& f = p["run"]["efficiency"];
        h += "<tr><td class=\"l\"><b>" + esc(p["name"]) + "</b></td><td class=\"l\"><b>frame</b></td>" +
             numberCell(f["frame_ms"]) + "<td class=\"l\">every pass at its ceiling</td>" +
             numberCell(f["passes_at_ceiling_ms"]) + numberCell(f["percent_of_ceiling"]) + "</tr>\n";
        for (const json& e : f["passes"])
            h += "<tr><td class=\"l\">" + esc(p["name"]) + "</td><td class=\"l\">" + esc(e["pass"]) + "</td>" +
                 numberCell(e["measured_ms"]) + limitCell(e) + "</tr>\n";
    }
    return h + "</table>\n";
}

} // namespace

std::string efficiencySection(const json& r) {
    std::string h = "<h2>Each pass against the device's ceilings (" + esc(r["device"]["name"]) + ")</h2>\n";
    const json& cal = r["calibration"];
    if (!cal.value("available", false))
        return h + "<p>Left out: " + esc(cal.value("why", std::string("no calibration"))) +
               ". Run <code>triptych calibrate</code> once on this device, then compare again.</p>\n";
    h += "<p>Ceilings measured by <code>triptych calibrate</code> on " + esc(cal["measured_at"]) +
         " (" + esc(cal["path"]) + "). A pass's binding ceiling is the one its counted work would take "
         "longest at; \"% of it\" is that time over the measured one. What is counted, and what is exact or "
         "a bound: docs/efficiency.md. The roofline places the passes that evaluate lights: their light "
         "evaluations as the FLOPs of the FMA loop that takes as long on the same stage, against the bytes "
         "their declared uses move; the solid roof is compute's, the dashed one the fragment stage's.</p>\n";
    return h + rooflineSvg(r) + passTable(r);
}

} // namespace tp::cli::html
