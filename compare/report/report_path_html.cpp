// report.html's "Camera path" section (compare --camera-path / --light-motion): the percentile
// table, frame time and error along the path for every pipeline with the views where their
// ranking flips marked, and what the images below show (the worst view).
#include <cmath>

#include "compare/report/report_html_parts.h"
#include "compare/report/svg_plot.h"
#include "core/renderer/pipeline_colour.h"

namespace tp::cli::html {
namespace {

using json = nlohmann::json;

std::vector<double> values(const json& a) {
    std::vector<double> v;
    for (const json& x : a)
        v.push_back(x.is_number() ? x.get<double>() : NAN);
    return v;
}

std::string percentileCells(const json& p) {
    if (p.is_null()) return "<td>-</td><td>-</td><td>-</td><td>-</td>";
    return numberCell(p["median"]) + numberCell(p["p95"]) + numberCell(p["p99"]) +
           numberCell(p["max"]);
}

std::string percentileTable(const json& path) {
    std::string t = "<table><tr><th class=\"l\">pipeline</th><th>frame ms median</th><th>p95</th>"
                    "<th>p99</th><th>max</th><th>view update ms median</th><th>max</th>"
                    "<th>rmse (hdr) median</th><th>p95</th><th>max</th><th>updates</th>"
                    "<th>replans</th><th class=\"l\">status</th></tr>\n";
    for (const json& p : path["pipelines"]) {
        const json& s = p["summary"];
        const json& u = s["view_update_ms"];
        const json& e = s["rmse_hdr"];
        t += "<tr><td class=\"l\">" + esc(p["name"]) + "</td>" + percentileCells(s["frame_ms"]) +
             (u.is_null() ? "<td>-</td><td>-</td>" : numberCell(u["median"]) + numberCell(u["max"])) +
             (e.is_null() ? "<td>-</td><td>-</td><td>-</td>"
                          : numberCell(e["median"]) + numberCell(e["p95"]) + numberCell(e["max"])) +
             "<td>" + esc(p["updates"]) + "</td><td>" + esc(p["replans"]) + "</td><td class=\"l\">" +
             (p["error"].get<std::string>().empty() ? std::string("ok") : esc(p["error"])) +
             "</td></tr>\n";
    }
    return t + "</table>\n";
}

std::string flipList(const json& path) {
    if (path["rank_flips"].empty())
        return "<p>The ranking of the pipelines by frame time holds over the whole path (no "
               "pipeline overtakes another by more than " +
               formatNumber(100.0 * path["rank_margin"].get<double>()) + " %).</p>\n";
    std::string h = "<p>The ranking by frame time flips at " +
                    std::to_string(path["rank_flips"].size()) +
                    " views (dashed lines; a pipeline overtakes another by more than " +
                    formatNumber(100.0 * path["rank_margin"].get<double>()) +
                    " %):</p>\n<ul>\n";
    auto order = [](const json& names) {
        std::string s;
        for (const json& n : names)
            s += (s.empty() ? "" : " &lt; ") + esc(n);
        return s;
    };
    for (const json& f : path["rank_flips"])
        h += "<li>view " + esc(f["view"]) + ": " + order(f["before"]) + " &rarr; " +
             order(f["after"]) + "</li>\n";
    return h + "</ul>\n";
}

} // namespace

std::string pathSection(const json& r) {
    if (!r.contains("path")) return "";
    const json& path = r["path"];
    std::vector<Series> times, errors;
    std::vector<double> marks;
    for (const json& f : path["rank_flips"])
        marks.push_back(f["view"].get<double>());
    for (const json& p : path["pipelines"]) {
        const std::string name = p["name"].get<std::string>();
        times.push_back({name, pipelineColour(name), values(p["frame_ms"])});
        errors.push_back({name, pipelineColour(name), values(p["rmse_hdr"])});
    }
    return "<h2>Camera path: " + esc(path["views"]) + " views of " + esc(path["source"]) +
           ", lights " + esc(path["light_motion"]) + "</h2>\n<p>" + esc(path["timing"]) +
           ". Device: " + esc(r["device"]["name"]) + ". The reference was rendered at " +
           esc(path["reference"]["renders"]) + " views and reused at " +
           esc(path["reference"]["reused"]) + " where nothing moved. The images and tables below " +
           "are of the path's worst view, " + esc(path["worst_view"]) +
           " (the largest error of any pipeline).</p>\n" + percentileTable(path) + flipList(path) +
           seriesPlotSvg(times, "view", "GPU frame (ms)", marks) +
           seriesPlotSvg(errors, "view", "rmse against the reference (linear)", marks);
}

} // namespace tp::cli::html
