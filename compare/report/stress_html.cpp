// stress.html from stress.json: a verdict matrix (case x pipeline), then per case what it
// stresses, what is expected, each pipeline's figures against its bound, and the images
// beside their difference maps. Everything inline (PNG data URIs), no script: opens offline.
#include "compare/report/report_html.h"
#include "compare/report/report_html_parts.h"
#include "compare/report/stress_report.h"
#include "compare/report/svg_plot.h"
#include "core/renderer/pipeline_colour.h"

namespace tp::cli {
namespace {

using nlohmann::json;
using html::esc;
using html::figure;

// After reportPageStyle(): verdict cells and a three-column image grid.
const char* kStressStyle = R"(
td.pass{background:#e3f6e3}td.fail{background:#fde2e2;font-weight:bold}
.grid{display:grid;grid-template-columns:repeat(3,minmax(0,1fr));gap:10px;max-width:1000px}
summary{font-weight:normal}
.sw{display:inline-block;width:10px;height:10px;margin-right:5px;border-radius:2px}
)";

// A pipeline's name behind a swatch of its colour on every page (core/renderer/pipeline_colour.h).
std::string pipelineName(const json& name) {
    const std::string n = name.get<std::string>();
    return std::string("<span class=\"sw\" style=\"background:") + paletteHex(pipelineColour(n)) +
           "\"></span>" + escapeXml(n);
}

std::string num(const json& j) {
    return j.is_number() ? formatNumber(j.get<double>()) : "&ndash;";
}

const json* checkNamed(const json& p, const std::string& name) {
    for (const json& c : p["checks"])
        if (c["name"] == name) return &c;
    return nullptr;
}

std::string verdictCell(const json& p) {
    const bool pass = p["verdict"] == "pass";
    std::string figure;
    if (const json* c = checkNamed(p, "tonemapped max |p - r|"))
        figure = " " + num((*c)["measured"]) + " / " + num((*c)["limit"]);
    return "<td class=\"" + std::string(pass ? "pass" : "fail") + "\">" + (pass ? "pass" : "FAIL") +
           figure + "</td>";
}

std::string matrix(const json& r) {
    std::string h =
        "<h2>Verdicts</h2>\n<p class=\"meta\">Each cell: verdict, then the tonemapped max "
        "|pipeline "
        "&minus; reference| / its derived bound.</p>\n<table><tr><th class=\"l\">case</th>";
    if (r["cases"].empty()) return h + "</tr></table>\n";
    for (const json& p : r["cases"][0]["pipelines"])
        h += "<th>" + pipelineName(p["name"]) + "</th>";
    h += "</tr>\n";
    for (const json& c : r["cases"]) {
        h += "<tr><td class=\"l\"><a href=\"#" + esc(c["name"]) + "\">" + esc(c["name"]) +
             "</a></td>";
        for (const json& p : c["pipelines"])
            h += verdictCell(p);
        h += "</tr>\n";
    }
    return h + "</table>\n";
}

std::string failedChecks(const json& p) {
    std::string s;
    for (const json& c : p["checks"])
        if (!c["pass"].get<bool>())
            s += (s.empty() ? "" : "<br>") + esc(c["name"]) + ": " + num(c["measured"]) +
                 " (limit " + num(c["limit"]) + ")";
    return s.empty() ? "&ndash;" : s;
}

std::string caseTable(const json& c) {
    std::string t =
        "<table><tr><th class=\"l\">pipeline</th><th>verdict</th><th>tonemapped max "
        "(bound)</th><th>RMSE "
        "(HDR)</th><th>max |d| (HDR)</th><th>NaN px</th><th>Inf px</th><th>lights dropped</th><th "
        "class=\"l\">beyond 65,504</th><th>depth px &ne; ref</th><th class=\"l\">failed "
        "checks</th></tr>\n";
    for (const json& p : c["pipelines"]) {
        t += "<tr><td class=\"l\">" + pipelineName(p["name"]) + "</td>" + verdictCell(p);
        if (p["status"] != "ok") {
            t += "<td colspan=\"9\" class=\"l\">did not run: " + esc(p.value("error", json(""))) +
                 "</td></tr>\n";
            continue;
        }
        const json& e = p["error_vs_reference"]["hdr"];
        t += "<td>" + num(p["checked_max_tonemapped"]) + " (" +
             num(p["bound"].value("tonemapped", json())) + ")</td>" + "<td>" + num(e["rmse"]) +
             "</td><td>" + num(e["max_abs"]) + "</td><td>" + num(p["nan_pixels"]) + "</td><td>" +
             num(p["inf_pixels"]) + "</td><td>" + num(p["lights_dropped"]) +
             "</td><td class=\"l\">" + esc(p["beyond_half_float"]["behaviour"]) + "</td><td>" +
             num(p["depth_mismatch_pixels"]) + "</td><td class=\"l\">" + failedChecks(p) +
             "</td></tr>\n";
    }
    return t + "</table>\n";
}

std::string boundDetails(const json& c) {
    std::string h = "<details><summary>bounds and checks, term by term</summary>";
    for (const json& p : c["pipelines"]) {
        if (!p.contains("bound")) continue;
        h += "<p class=\"meta\"><b>" + esc(p["name"]) + "</b>: " + esc(p["bound"]["why"]) +
             "</p><table>";
        for (const json& t : p["bound"]["terms"])
            h += "<tr><td class=\"l\">" + esc(t["name"]) + "</td><td>" + num(t["relative"]) +
                 "</td><td>" + num(t["absolute"]) + "</td><td class=\"l\">" + esc(t["why"]) +
                 "</td></tr>";
        for (const json& k : p["checks"])
            h += "<tr><td class=\"l\">check: " + esc(k["name"]) + "</td><td>" + num(k["measured"]) +
                 "</td><td>" + num(k["limit"]) + "</td><td class=\"l\">" + esc(k["why"]) +
                 "</td></tr>";
        h += "</table>";
    }
    return h + "</details>\n";
}

// A shadowed case: the shadow technique's checks (the maps reference against the rays one),
// then the rays reference and the heat map of maps - rays.
Result<std::string> shadowSection(const json& c, const std::string& outDir) {
    if (!c.contains("shadow_technique")) return std::string();
    const json& t = c["shadow_technique"];
    const bool pass = t["verdict"] == "pass";
    std::string h = "<h3>Shadow technique: " + std::string(pass ? "pass" : "FAIL") +
                    "</h3>\n<p class=\"meta\">The reference on the pipelines' shadow maps (the "
                    "reference above, which the pipelines are measured against) against the "
                    "ray-traced one; bounds from the maps' texel footprint and the filter "
                    "(docs/stress.md, \"Shadowed cases\").</p>\n<table><tr><th "
                    "class=\"l\">check</th><th>measured</th><th>limit</th><th "
                    "class=\"l\">why</th></tr>\n";
    for (const json& k : t["checks"])
        h += "<tr><td class=\"l " + std::string(k["pass"].get<bool>() ? "pass" : "fail") +
             "\">" + esc(k["name"]) + "</td><td>" + num(k["measured"]) + "</td><td>" +
             num(k["limit"]) + "</td><td class=\"l\">" + esc(k["why"]) + "</td></tr>\n";
    h += "</table>\n<div class=\"grid\">\n";
    for (const json& f : t["reference_rays"]["files"]) {
        const std::string file = f;
        if (!file.ends_with(".png")) continue;
        Result<std::string> fig = figure(
            outDir, file, file.ends_with("_diff.png") ? "maps &minus; rays" : "reference (rays)");
        if (!fig) return fig;
        h += *fig;
    }
    return h + "</div>\n";
}

Result<std::string> caseSection(const json& c, const std::string& outDir) {
    const bool pass = c["verdict"] == "pass";
    const json& s = c["settings"];
    std::string h = "<h2 id=\"" + esc(c["name"]) + "\">" + esc(c["name"]) + ": " +
                    (pass ? "pass" : "FAIL") + "</h2>\n";
    h += "<p class=\"meta\"><b>Stresses:</b> " + esc(c["stresses"]) + "<br><b>Expected:</b> " +
         esc(c["expectation"]) + "<br>" + esc(s["width"]) + "&times;" + esc(s["height"]) + ", " +
         esc(s["msaa"]) + "&times; MSAA, " + esc(c["lights"]) + " lights, " + esc(c["triangles"]) +
         " triangles, exposure " + num(c["exposure_ev"]) + " EV, " + num(c["seconds"]) +
         " s.</p>\n";
    if (c["reference"]["status"] != "ok")
        h += "<div class=\"failed\">reference failed: " +
             esc(c["reference"].value("error", json(""))) + "</div>\n";
    h += caseTable(c) + boundDetails(c);
    Result<std::string> shadow = shadowSection(c, outDir);
    if (!shadow) return shadow;
    h += *shadow;
    h += "<p class=\"meta\">Per pipeline: the reference, the pipeline, and the heat map of "
         "|pipeline &minus; reference| "
         "(max over RGB, linear) from 0 to " +
         num(c["difference_scale"]["value"]) +
         " (one scale per case); magenta: NaN/Inf.</p>\n<div class=\"grid\">\n";
    std::string ref;
    for (const json& f : c["reference"]["files"])
        if (f.get<std::string>().ends_with(".png")) {
            Result<std::string> fig = figure(outDir, f, "reference");
            if (!fig) return fig;
            ref = *fig;
        }
    for (const json& p : c["pipelines"]) {
        h += ref;
        for (const json& f : p["files"]) {
            const std::string file = f;
            if (!file.ends_with(".png")) continue;
            Result<std::string> fig =
                figure(outDir, file,
                       esc(p["name"]) + (file.ends_with("_diff.png") ? " &minus; reference" : ""));
            if (!fig) return fig;
            h += *fig;
        }
        if (p["status"] != "ok")
            h += "<figure><figcaption>" + esc(p["name"]) +
                 " did not run</figcaption></figure><figure></figure>\n";
    }
    return h + "</div>\n";
}

} // namespace

Result<std::string> stressHtml(const json& r, const std::string& outDir) {
    std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta "
                    "charset=\"utf-8\"><title>triptych stress</title>\n<style>";
    h += reportPageStyle();
    h += kStressStyle;
    const json& sum = r["summary"];
    h += "</style></head><body>\n<h1>triptych stress: " + esc(sum["passed"]) + " of " +
         esc(sum["cases"]) + " cases pass</h1>\n<p class=\"meta\">Device: <b>" +
         esc(r["device"]["name"]) + "</b> (" + esc(r["device"]["driver"]) + ")<br>Command: <code>" +
         esc(r["command"]) +
         "</code><br>Tonemapped bounds: K = " + num(r["tonemap_slopes"]["relative_K"]) +
         ", S0 = " + num(r["tonemap_slopes"]["absolute_S0"]) + " (" +
         esc(r["tonemap_slopes"]["rule"]) + "); docs/stress.md derives every term.</p>\n";
    for (const json& m : r["validation_messages"])
        h += "<div class=\"failed\">validation: " + esc(m) + "</div>\n";
    h += matrix(r);
    for (const json& c : r["cases"]) {
        Result<std::string> s = caseSection(c, outDir);
        if (!s) return s;
        h += *s;
    }
    return h + "<p class=\"meta\">Schema " + esc(r["schema"]) +
           "; every number above is in stress.json.</p>\n</body></html>\n";
}

} // namespace tp::cli
