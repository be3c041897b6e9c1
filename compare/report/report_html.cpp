// report.html from report.json: what a person reads first. Everything is inline (images as
// data URIs, CSS, SVG, the flip/loupe script) so the page opens offline from any directory; numbers
// come from report.json only, so the page and the JSON cannot disagree.
#include "compare/report/report_html.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "compare/report/report_html_parts.h"
#include "compare/report/report_viewer_js.h"
#include "compare/report/svg_plot.h"
#include "core/util/files.h"

namespace tp::cli {

using nlohmann::json;

namespace html {

std::string esc(const json& j) {
    return escapeXml(j.is_string() ? j.get<std::string>() : j.dump());
}

std::string numberCell(const json& j) {
    if (j.is_null()) return "<td>inf</td>";
    return "<td>" + formatNumber(j.get<double>()) + "</td>";
}

double frameMedian(const json& outcome) {
    for (const json& t : outcome["run"]["timings"])
        if (t["pass"] == "frame") return t["median_ms"].get<double>();
    return 0.0;
}

bool ok(const json& outcome) {
    return outcome["status"] == "ok";
}

std::string joulesCell(const json& run) {
    const json& e = run.value("energy", json::object());
    if (e.value("joules_per_frame", json()).is_number()) return numberCell(e["joules_per_frame"]);
    return "<td title=\"" + esc(e.value("reason", "not measured")) + "\">&ndash;</td>";
}

// Each run's energy per frame beside its frame time, with the window it was measured over,
// or why it is unknown (docs/efficiency.md, "Energy per frame").
std::string energySection(const json& r) {
    const json& source = r["energy_source"];
    std::string h = "<h2>Energy per frame (" + esc(r["device"]["name"]) + ")</h2>\n";
    if (!source.value("available", false))
        return h + "<p>Not measured: " + esc(source.value("reason", "")) + ".</p>\n";
    h += "<p>" + esc(source["source"]) + " counter of " + esc(source["device"]) +
         ", read before the first timed frame and after the last; a window shorter than " +
         formatNumber(source["min_window_ms"].get<double>()) +
         " ms runs the same frames on (untimed). Idle power is in the count.</p>\n"
         "<table><tr><th class=\"l\">pipeline</th><th>frame median ms</th><th>J / frame</th>"
         "<th>mean W</th><th>window ms</th><th>frames</th><th class=\"l\">note</th></tr>\n";
    auto row = [&](const json& p) {
        if (!ok(p)) return;
        const json& e = p["run"]["energy"];
        const bool known = e["joules_per_frame"].is_number();
        h += "<tr><td class=\"l\">" + esc(p["name"]) + "</td><td>" + formatNumber(frameMedian(p)) + "</td>" +
             joulesCell(p["run"]) +
             (e.contains("watts") ? numberCell(e["watts"]) + numberCell(e["window_ms"]) + "<td>" +
                                        esc(e["frames"]) + "</td>"
                                  : std::string("<td></td><td></td><td></td>")) +
             "<td class=\"l\">" +
             (known ? (e.value("extended_frames", 0) > 0 ? "window extended by " + esc(e["extended_frames"]) +
                                                               " untimed frames"
                                                         : std::string())
                    : esc(e.value("reason", ""))) +
             "</td></tr>\n";
    };
    row(r["reference"]);
    for (const json& p : r["pipelines"])
        row(p);
    return h + "</table>\n";
}

Result<std::string> figure(const std::string& outDir, const std::string& file,
                           const std::string& caption, const std::string& attributes) {
    Result<std::string> bytes = readWholeFile(outDir + "/" + file);
    if (!bytes) return Error{bytes.error()};
    return "<figure><img alt=\"" + escapeXml(file) + "\"" + attributes +
           " src=\"data:image/png;base64," + base64(*bytes) + "\"><figcaption>" + caption +
           "</figcaption></figure>\n";
}

} // namespace html

using namespace html;

namespace {

// The rules of every triptych page (compare, stress); each page adds its own after them.
const char* kBaseStyle = R"(
body{font-family:sans-serif;margin:16px 24px;color:#222;max-width:1400px}
h1{font-size:22px;margin:4px 0}h2{font-size:18px;margin:28px 0 8px;border-bottom:1px solid #ccc}
table{border-collapse:collapse;font-size:13px;margin:6px 0}
td,th{border:1px solid #ccc;padding:3px 7px;text-align:right}th{background:#f0f0f0}
td.l,th.l{text-align:left}td.warn{background:#fff6d6}
.meta{font-size:13px;color:#444}.meta code{background:#f4f4f4;padding:1px 4px;word-break:break-all}
.failed{background:#fde2e2;border:1px solid #d33;padding:8px;margin:8px 0}
.note{background:#fff6d6;border:1px solid #e0c040;padding:6px;margin:8px 0;font-size:13px}
figure{margin:0}figure img{width:100%;image-rendering:pixelated;border:1px solid #999}
figcaption{font-size:12px;color:#333;margin-top:2px}
details{margin:6px 0}summary{cursor:pointer;font-weight:bold}
)";

const char* kStyle = R"(
.grid{display:grid;grid-template-columns:repeat(3,minmax(0,1fr));gap:12px}
table.pairs td{width:300px;vertical-align:top}table.pairs img{width:300px}
)";

std::string header(const json& r) {
    const json& s = r["settings"];
    std::string h =
        "<h1>triptych compare: " + esc(r["scene"]["path"]) + "</h1>\n<p class=\"meta\">";
    h += std::to_string(s["width"].get<int>()) + "&times;" +
         std::to_string(s["height"].get<int>()) + ", " + std::to_string(s["msaa"].get<int>()) +
         "&times; MSAA, " + std::to_string(r["scene"]["lights"].get<int>()) + " lights (seed " +
         esc(r["seed"]) + "), " + std::to_string(r["scene"]["triangles"].get<int>()) +
         " triangles; " + std::to_string(s["warmup"].get<int>()) + " warm-up + " +
         std::to_string(s["frames"].get<int>()) + " timed frames per pipeline; exposure " +
         formatNumber(s["exposure_ev"].get<double>()) + " EV for every PNG.<br>Device: <b>" +
         esc(r["device"]["name"]) + "</b> (" + esc(r["device"]["driver"]) + ")<br>Camera: " +
         (r.contains("camera_source") ? esc(r["camera_source"]["description"])
                                      : std::string("&ndash;")) +
         " (as a <code>--camera</code> file: camera.json)<br>Command: <code>" + esc(r["command"]) +
         "</code></p>\n";
    if (r["device"].contains("note"))
        h += "<div class=\"note\">" + esc(r["device"]["note"]) + ".</div>\n";
    for (const json& p : r["pipelines"])
        if (!ok(p))
            h += "<div class=\"failed\"><b>" + esc(p["name"]) + " failed:</b> " + esc(p["error"]) +
                 "</div>\n";
    for (const json& m : r["validation_messages"])
        h += "<div class=\"failed\">validation: " + esc(m) + "</div>\n";
    return h;
}

Result<std::string> imagesSection(const json& r, const std::string& outDir) {
    std::string h = "<h2>Images and differences</h2>\n<p class=\"meta\">Left: tonemapped image. "
                    "Middle: heat map of "
                    "|pipeline &minus; reference| (max over RGB, linear), one scale for the whole "
                    "report: 0 to " +
                    formatNumber(r["difference_scale"]["value"].get<double>()) + " (" +
                    esc(r["difference_scale"]["rule"]) +
                    "). Magenta: NaN/Inf. Right: the HDR-FLIP error map (0 to 1, magma as in FLIP; "
                    "see FLIP below). "
                    "<b>Flip</b>: click a pipeline's image, or press F over it, to swap it in "
                    "place with the reference "
                    "(F elsewhere flips them all). <b>Loupe</b>: hover any image for its pixels, "
                    "magnified.</p>\n"
                    "<div class=\"grid\">\n";
    Result<std::string> ref = figure(outDir, "reference.png", "reference", " id=\"img-reference\"");
    if (!ref) return ref;
    h += *ref + "<figure><figcaption>The reference: every light at every "
                "sample.</figcaption></figure><figure></figure>\n";
    for (const json& p : r["pipelines"]) {
        if (!ok(p)) continue;
        const std::string name = p["name"];
        const json& e = p["error_vs_reference"];
        Result<std::string> img =
            figure(outDir, name + ".png", escapeXml(name) + " <span class=\"flip-state\"></span>",
                   " class=\"flip\" data-pipeline=\"" + escapeXml(name) + "\"");
        Result<std::string> diff =
            figure(outDir, name + "_diff.png",
                   escapeXml(name) + " &minus; reference: RMSE " +
                       formatNumber(e["hdr"]["rmse"].get<double>()) + ", max " +
                       formatNumber(e["hdr"]["max_abs"].get<double>()) + " (HDR)");
        if (!img) return img;
        if (!diff) return diff;
        h += *img + *diff;
        if (flipValue(p, "hdr", "mean").is_number()) {
            Result<std::string> flip = figure(
                outDir, name + "_flip.png",
                "HDR-FLIP " + escapeXml(name) + " vs reference (magma, 0 to 1): mean " +
                    formatNumber(flipValue(p, "hdr", "mean").get<double>()) + ", weighted median " +
                    formatNumber(flipValue(p, "hdr", "weighted_median").get<double>()) +
                    "; FLIP of the PNGs: mean " +
                    formatNumber(flipValue(p, "ldr", "mean").get<double>()) + " (" +
                    escapeXml(name) + "_flip_ldr.png)");
            if (!flip) return flip;
            h += *flip;
        } else
            h += "<figure></figure>\n";
    }
    return h + "</div>\n";
}

std::string timingSection(const json& r) {
    std::vector<BarGroup> groups;
    auto add = [&](const json& p) {
        if (!ok(p)) return;
        BarGroup g{p["name"].get<std::string>(), {}, pipelineColour(p["name"].get<std::string>())};
        for (const json& t : p["run"]["timings"])
            g.bars.push_back({t["pass"].get<std::string>(), t["median_ms"].get<double>()});
        groups.push_back(std::move(g));
    };
    add(r["reference"]);
    for (const json& p : r["pipelines"])
        add(p);
    std::string h = "<h2>GPU time per pass (median over timed frames, " + esc(r["device"]["name"]) +
                    ")</h2>\n" + barChartSvg(groups, "ms");
    h += "<details><summary>median / min / max per pass</summary><table><tr><th "
         "class=\"l\">pipeline</th><th "
         "class=\"l\">pass</th><th>median ms</th><th>min ms</th><th>max ms</th><th>frames</th><th "
         "class=\"l\">device</th></tr>\n";
    auto rows = [&](const json& p) {
        if (!ok(p)) return;
        for (const json& t : p["run"]["timings"])
            h += "<tr><td class=\"l\">" + esc(p["name"]) + "</td><td class=\"l\">" +
                 esc(t["pass"]) + "</td>" + numberCell(t["median_ms"]) + numberCell(t["min_ms"]) +
                 numberCell(t["max_ms"]) + "<td>" + esc(t["frames"]) + "</td><td class=\"l\">" +
                 esc(t["device"]) + "</td></tr>\n";
    };
    rows(r["reference"]);
    for (const json& p : r["pipelines"])
        rows(p);
    return h + "</table></details>\n";
}

std::string ledgerTable(const json& memory) {
    std::string t =
        "<table><tr><th class=\"l\">name</th><th class=\"l\">pass</th><th class=\"l\">kind</th><th "
        "class=\"l\">format</th><th>extent</th><th>samples</th><th>bytes</th><th "
        "class=\"l\">purpose</th></tr>\n";
    for (const json& e : memory["resources"])
        t += "<tr><td class=\"l\">" + esc(e["name"]) + "</td><td class=\"l\">" + esc(e["pass"]) +
             "</td><td class=\"l\">" + esc(e["kind"]) + "</td><td class=\"l\">" + esc(e["format"]) +
             "</td><td>" +
             (e["kind"] == "image" ? esc(e["width"]) + "&times;" + esc(e["height"])
                                   : std::string("")) +
             "</td><td>" + esc(e["samples"]) + "</td><td>" + esc(e["bytes"]) +
             "</td><td class=\"l\">" + esc(e["purpose"]) + "</td></tr>\n";
    return t + "<tr><th class=\"l\" colspan=\"6\">total</th><th>" + esc(memory["total_bytes"]) +
           "</th><th></th></tr></table>\n";
}

std::string memorySection(const json& r) {
    std::string h =
        "<h2>Memory</h2>\n<table><tr><th class=\"l\">owner</th><th>resources</th><th>total "
        "bytes</th><th>MiB</th><th>bytes / pixel</th></tr>\n";
    auto row = [&](const std::string& name, const json& mem) {
        h += "<tr><td class=\"l\">" + escapeXml(name) + "</td><td>" +
             std::to_string(mem["resources"].size()) + "</td><td>" + esc(mem["total_bytes"]) +
             "</td><td>" + formatNumber(mem["total_bytes"].get<double>() / 1048576.0) + "</td>" +
             (mem.contains("bytes_per_pixel") ? numberCell(mem["bytes_per_pixel"])
                                              : "<td>&ndash;</td>") +
             "</tr>\n";
    };
    row("scene (shared, counted once)", r["shared_memory"]);
    if (ok(r["reference"])) row("reference", r["reference"]["run"]["memory"]);
    for (const json& p : r["pipelines"])
        if (ok(p)) row(p["name"], p["run"]["memory"]);
    h += "</table>\n";
    auto details = [&](const std::string& name, const json& mem) {
        h += "<details><summary>" + escapeXml(name) + "</summary>" + ledgerTable(mem) +
             "</details>\n";
    };
    if (ok(r["reference"])) details("reference", r["reference"]["run"]["memory"]);
    for (const json& p : r["pipelines"])
        if (ok(p)) details(p["name"], p["run"]["memory"]);
    details("scene (shared)", r["shared_memory"]);
    return h;
}

// One pair: its heat map (a - b on the report's scale) with the numbers under it.
Result<std::string> pairCell(const json& pair, const std::string& outDir) {
    const std::string a = pair["a"], b = pair["b"];
    std::string caption = escapeXml(a) + " &minus; " + escapeXml(b) + ": RMSE " +
                          formatNumber(pair["hdr"]["rmse"].get<double>()) + ", max " +
                          formatNumber(pair["hdr"]["max_abs"].get<double>()) + " (HDR)";
    for (const json& f : pair.value("files", json::array()))
        if (const std::string file = f; file.ends_with(".png"))
            return figure(outDir, file, caption);
    return "<p class=\"meta\">" + caption + "</p>\n";
}

// A matrix: row a, column b holds the map of a - b (upper triangle; the lower one would
// repeat it with the sign flipped), then every number in a table.
Result<std::string> pairwiseSection(const json& r, const std::string& outDir) {
    if (r["pairwise"].empty()) return std::string();
    std::vector<std::string> rows, cols;
    auto add = [](std::vector<std::string>& v, const std::string& n) {
        if (std::find(v.begin(), v.end(), n) == v.end()) v.push_back(n);
    };
    for (const json& p : r["pairwise"]) {
        add(rows, p["a"]);
        add(cols, p["b"]);
    }
    std::string h = "<h2>Pipelines against each other</h2>\n<p class=\"meta\">Row a, column b: "
                    "heat map of |a &minus; b| "
                    "(max over RGB, linear) on the same scale as the maps above (0 to " +
                    formatNumber(r["difference_scale"]["value"].get<double>()) +
                    "; above it saturates). Signed differences: a_vs_b_diff.exr.</p>\n<table "
                    "class=\"pairs\"><tr><th></th>";
    for (const std::string& c : cols)
        h += "<th>" + escapeXml(c) + "</th>";
    h += "</tr>\n";
    for (const std::string& a : rows) {
        h += "<tr><th class=\"l\">" + escapeXml(a) + "</th>";
        for (const std::string& b : cols) {
            auto it = std::find_if(r["pairwise"].begin(), r["pairwise"].end(),
                                   [&](const json& p) { return p["a"] == a && p["b"] == b; });
            if (it == r["pairwise"].end()) {
                h += "<td></td>";
                continue;
            }
            Result<std::string> cell = pairCell(*it, outDir);
            if (!cell) return cell;
            h += "<td class=\"l\">" + *cell + "</td>";
        }
        h += "</tr>\n";
    }
    h += "</table>\n<table><tr><th class=\"l\">a</th><th class=\"l\">b</th><th>RMSE "
         "(HDR)</th><th>max |a&minus;b| "
         "(HDR)</th><th>99th percentile |a&minus;b|</th><th>PSNR dB (tonemapped)</th><th>max "
         "(tonemapped)</th></tr>\n";
    for (const json& p : r["pairwise"])
        h += "<tr><td class=\"l\">" + esc(p["a"]) + "</td><td class=\"l\">" + esc(p["b"]) +
             "</td>" + numberCell(p["hdr"]["rmse"]) + numberCell(p["hdr"]["max_abs"]) +
             numberCell(p.value("difference_p99", json(nullptr))) +
             numberCell(p["tonemapped"]["psnr"]) + numberCell(p["tonemapped"]["max_abs"]) +
             "</tr>\n";
    return h + "</table>\n";
}

std::string detailsSection(const json& r) {
    std::string h = "<h2>Counters and what was left out</h2>\n";
    auto block = [&](const json& p) {
        if (!ok(p)) return;
        h += "<details><summary>" + esc(p["name"]) + "</summary><table>";
        for (const auto& [k, v] : p["run"]["counters"].items())
            h += "<tr><td class=\"l\">" + escapeXml(k) + "</td>" + numberCell(v) + "</tr>";
        h += "</table><ul>";
        for (const json& l : p["run"]["left_out"])
            h += "<li>left out: " + esc(l["what"]) + " &mdash; " + esc(l["why"]) + "</li>";
        for (const json& c : p["run"]["culled_passes"])
            h += "<li>culled pass: " + esc(c) + "</li>";
        h += "</ul></details>\n";
    };
    block(r["reference"]);
    for (const json& p : r["pipelines"])
        block(p);
    h += "<h2>Metrics</h2>\n<table>";
    for (const json& m : r["metrics_table"]["metrics"])
        h += "<tr><td class=\"l\">" + esc(m["name"]) + "</td><td class=\"l\">" +
             esc(m["description"]) + "</td></tr>";
    return h + "</table>\n<p class=\"meta\">HDR PSNR peak: " +
           formatNumber(r["metrics_table"]["psnr_peak_hdr"].get<double>()) + " (" +
           esc(r["metrics_table"]["hdr_psnr_peak_rule"]) + "); tonemapped PSNR peak 1.</p>\n";
}

} // namespace

std::string base64(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16 | uint32_t(uint8_t(bytes[i + 1])) << 8 |
                     uint8_t(bytes[i + 2]);
        for (int s = 18; s >= 0; s -= 6)
            out += table[(v >> s) & 63];
    }
    if (i < bytes.size()) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

Result<std::string> reportHtml(const json& r, const std::string& outDir) {
    std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta "
                    "charset=\"utf-8\"><title>triptych compare</title>\n<style>";
    h += kBaseStyle;
    h += kStyle;
    h += reportViewerStyle();
    h += "</style></head><body>\n" + header(r) + pathSection(r) + summaryTable(r) +
         (hasCenterReference(r) ? twoReferences(r) : "") +
         (hasShadowMapReference(r) ? shadowReferences(r) : "") + errorPlot(r);
    Result<std::string> images = imagesSection(r, outDir);
    if (!images) return images;
    Result<std::string> pairs = pairwiseSection(r, outDir);
    if (!pairs) return pairs;
    h +=
        *images + flipSection(r) + *pairs + timingSection(r) + energySection(r) + efficiencySection(r) + memorySection(r) +
        detailsSection(r);
    return h + "<p class=\"meta\">Schema " + esc(r["schema"]) +
           "; every number above is in report.json.</p>\n" + reportViewerScript() +
           "</body></html>\n";
}

const char* reportPageStyle() {
    return kBaseStyle;
}

} // namespace tp::cli
