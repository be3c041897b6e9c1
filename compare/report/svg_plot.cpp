// SVG charts for report.html. Coordinates are computed here so the page needs no script;
// colours come from one small palette that reads on white and in greyscale.
#include "compare/report/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/renderer/pipeline_colour.h"
#include "core/renderer/renderer.h"

namespace tp::cli {
namespace {

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", v);
    return buf;
}

std::string text(double x, double y, const std::string& s, const char* anchor = "start",
                 int size = 12, const char* extra = "") {
    return "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" text-anchor=\"" + anchor +
           "\" font-size=\"" + std::to_string(size) + "\"" + extra + ">" + escapeXml(s) +
           "</text>\n";
}

std::string line(double x1, double y1, double x2, double y2, const char* stroke, double w = 1) {
    return "<line x1=\"" + num(x1) + "\" y1=\"" + num(y1) + "\" x2=\"" + num(x2) + "\" y2=\"" +
           num(y2) + "\" stroke=\"" + stroke + "\" stroke-width=\"" + num(w) + "\"/>\n";
}

// A log axis range covering [lo, hi] with a margin, in log10 units.
std::pair<double, double> logRange(double lo, double hi) {
    double a = std::log10(lo), b = std::log10(hi);
    if (b - a < 0.5) {
        double mid = 0.5 * (a + b);
        a = mid - 0.25;
        b = mid + 0.25;
    }
    double pad = 0.08 * (b - a);
    return {a - pad, b + pad};
}

// Tick values 1, 2, 5 x 10^k inside [10^a, 10^b]; only powers of ten when that is too many.
std::vector<double> logTicks(double a, double b) {
    std::vector<double> ticks;
    for (int k = int(std::floor(a)); k <= int(std::ceil(b)); ++k)
        for (double m : {1.0, 2.0, 5.0}) {
            double v = m * std::pow(10.0, k);
            if (std::log10(v) >= a && std::log10(v) <= b) ticks.push_back(v);
        }
    if (ticks.size() < 3) { // a narrow range: every integer multiple of the decade
        ticks.clear();
        for (int k = int(std::floor(a)); k <= int(std::ceil(b)); ++k)
            for (int m = 1; m <= 9; ++m) {
                double v = m * std::pow(10.0, k);
                if (std::log10(v) >= a && std::log10(v) <= b) ticks.push_back(v);
            }
    }
    if (ticks.size() > 10) {
        std::vector<double> decades;
        for (double v : ticks)
            if (std::abs(std::log10(v) - std::round(std::log10(v))) < 1e-9) decades.push_back(v);
        if (decades.size() >= 2) return decades;
    }
    return ticks;
}

std::string tickLabel(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

} // namespace

std::string escapeXml(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (char c : s) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        case '\'':
            out += "&#39;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string barChartSvg(const std::vector<BarGroup>& groups, const std::string& unit, int width) {
    const double rowH = 18, labelW = 220, valueW = 110, top = 6;
    double maxValue = 0;
    int rows = 0;
    for (const BarGroup& g : groups) {
        rows += 1 + int(g.bars.size());
        for (const auto& b : g.bars)
            maxValue = std::max(maxValue, b.second);
    }
    if (!(maxValue > 0)) maxValue = 1;
    const double barW = width - labelW - valueW;
    const double height = top + rows * rowH + 8;
    std::string svg = "<svg width=\"" + std::to_string(width) + "\" height=\"" + num(height) +
                      "\" font-family=\"sans-serif\">\n";
    double y = top;
    for (size_t gi = 0; gi < groups.size(); ++gi) {
        const char* colour = paletteHex(groups[gi].colour >= 0 ? groups[gi].colour : int(gi));
        svg += text(4, y + 13, groups[gi].title, "start", 13, " font-weight=\"bold\"");
        y += rowH;
        for (const auto& [label, value] : groups[gi].bars) {
            double w = std::max(1.0, barW * value / maxValue);
            svg += text(labelW - 6, y + 13, label, "end");
            svg += "<rect x=\"" + num(labelW) + "\" y=\"" + num(y + 3) + "\" width=\"" + num(w) +
                   "\" height=\"" + num(rowH - 6) + "\" fill=\"" + colour + "\"" +
                   (label == "frame" ? " fill-opacity=\"0.45\"" : "") + "/>\n";
            svg += text(labelW + w + 6, y + 13, formatNumber(value) + " " + unit);
            y += rowH;
        }
    }
    return svg + "</svg>\n";
}

namespace {

// Series si's colour: its entry of `colours` when given, else its own index.
const char* seriesColour(size_t si, const std::vector<int>& colours) {
    const int c = si < colours.size() && colours[si] >= 0 ? colours[si] : int(si);
    return paletteHex(c);
}

// A series sharing its colour with earlier ones gets a dashed line (the n-th such: dash n).
std::string seriesDash(size_t si, const std::vector<int>& colours) {
    int before = 0;
    for (size_t k = 0; k < si && si < colours.size(); ++k)
        before += colours[k] == colours[si];
    static const char* kDashes[] = {"", "6 3", "2 2", "8 3 2 3", "1 3"};
    const char* d = kDashes[size_t(before) % std::size(kDashes)];
    return *d ? std::string(" stroke-dasharray=\"") + d + "\"" : "";
}

// Widens the data range to the lines' points.
void extendRange(const std::vector<PlotLine>& lines, double& xlo, double& xhi, double& ylo, double& yhi) {
    for (const PlotLine& l : lines)
        for (const auto& [x, y] : l.xy)
            if (x > 0 && y > 0)
                xlo = std::min(xlo, x), xhi = std::max(xhi, x), ylo = std::min(ylo, y), yhi = std::max(yhi, y);
}

// The lines as grey paths (dashed where asked), each labelled at its right end.
template <class Px, class Py> std::string linesSvg(const std::vector<PlotLine>& lines, Px px, Py py) {
    std::string svg;
    for (const PlotLine& l : lines) {
        std::string path;
        for (const auto& [x, y] : l.xy)
            path += (path.empty() ? "M" : " L") + num(px(x)) + "," + num(py(y));
        svg += "<path d=\"" + path + "\" fill=\"none\" stroke=\"#555\" stroke-width=\"2\"" +
               (l.dashed ? " stroke-dasharray=\"6 3\"" : "") + "/>\n";
        if (!l.xy.empty())
            svg += text(px(l.xy.back().first) - 4, py(l.xy.back().second) - 6, l.label, "end", 12);
    }
    return svg;
}

} // namespace

std::string scatterLogLogSvg(const std::vector<PlotPoint>& points, const std::string& xLabel,
                             const std::string& yLabel, int width, int height,
                             const std::vector<std::string>& seriesNames, bool joinSeries,
                             const std::vector<int>& seriesColours, const std::vector<PlotLine>& lines) {
    auto colourOf = [&](size_t si) { return seriesColour(si, seriesColours); };
    auto dashOf = [&](size_t si) { return seriesDash(si, seriesColours); };
    const double left = 80, right = 30, top = 20, bottom = 60;
    double xlo = INFINITY, xhi = 0, ylo = INFINITY, yhi = 0;
    bool anyZero = false;
    for (const PlotPoint& p : points) {
        if (p.x > 0) xlo = std::min(xlo, p.x), xhi = std::max(xhi, p.x);
        if (p.y > 0)
            ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
        else
            anyZero = true;
    }
    extendRange(lines, xlo, xhi, ylo, yhi);
    if (!(xhi > 0)) xlo = 1, xhi = 10;
    if (!(yhi > 0)) ylo = 1e-4, yhi = 1e-2;
    auto [xa, xb] = logRange(xlo, xhi);
    auto [ya, yb] = logRange(ylo, yhi);
    if (anyZero) ya -= 0.12 * (yb - ya); // room on the bottom edge for exact (zero-error) points
    const double pw = width - left - right, ph = height - top - bottom;
    auto px = [&](double v) {
        return left + pw * (std::log10(std::max(v, 1e-30)) - xa) / (xb - xa);
    };
    auto py = [&](double v) {
        return v > 0 ? top + ph * (yb - std::log10(v)) / (yb - ya) : top + ph;
    };

    std::string svg = "<svg width=\"" + std::to_string(width) + "\" height=\"" +
                      std::to_string(height) + "\" font-family=\"sans-serif\">\n";
    svg += "<rect x=\"" + num(left) + "\" y=\"" + num(top) + "\" width=\"" + num(pw) +
           "\" height=\"" + num(ph) + "\" fill=\"#fafafa\" stroke=\"#888\"/>\n";
    for (double t : logTicks(xa, xb)) {
        svg += line(px(t), top, px(t), top + ph, "#e2e2e2");
        svg += text(px(t), top + ph + 16, tickLabel(t), "middle", 11);
    }
    for (double t : logTicks(ya, yb)) {
        if (anyZero && py(t) > top + ph - 14) continue; // would collide with the "0" label
        svg += line(left, py(t), left + pw, py(t), "#e2e2e2");
        svg += text(left - 6, py(t) + 4, tickLabel(t), "end", 11);
    }
    if (anyZero) svg += text(left - 6, top + ph + 4, "0", "end", 11);
    svg += text(left + pw / 2, height - 18, xLabel + " (log)", "middle", 13);
    svg += "<text transform=\"translate(18," + num(top + ph / 2) +
           ") rotate(-90)\" text-anchor=\"middle\" "
           "font-size=\"13\">" +
           escapeXml(yLabel + " (log)") + "</text>\n";
    svg += linesSvg(lines, px, py);
    for (size_t si = 0; si < seriesNames.size(); ++si) {
        std::vector<std::pair<double, double>> xy;
        for (const PlotPoint& p : points)
            if (p.series == int(si)) xy.push_back({px(p.x), py(p.y)});
        std::sort(xy.begin(), xy.end());
        std::string path;
        for (const auto& [x, y] : xy)
            path += (path.empty() ? "M" : " L") + num(x) + "," + num(y);
        if (joinSeries && xy.size() > 1)
            svg += "<path d=\"" + path + "\" fill=\"none\" stroke=\"" + colourOf(si) +
                   "\" stroke-width=\"1.5\"" + dashOf(si) + "/>\n";
        double ly = top + 14 + 16 * double(si);
        svg += "<circle cx=\"" + num(left + 12) + "\" cy=\"" + num(ly - 4) + "\" r=\"5\" fill=\"" +
               colourOf(si) + "\"/>\n" + text(left + 22, ly, seriesNames[si]);
    }
    for (size_t i = 0; i < points.size(); ++i) {
        const PlotPoint& p = points[i];
        const char* colour = p.series >= 0 ? colourOf(size_t(p.series))
                             : paletteHex(p.colour >= 0 ? p.colour : int(i));
        double x = px(p.x), y = py(p.y);
        if (p.ring)
            svg += "<circle cx=\"" + num(x) + "\" cy=\"" + num(y) +
                   "\" r=\"10\" fill=\"none\" stroke=\"#000\" "
                   "stroke-width=\"1.5\"/>\n";
        svg += "<circle cx=\"" + num(x) + "\" cy=\"" + num(y) + "\" r=\"6\" fill=\"" + colour +
               "\" stroke=\"#000\" stroke-width=\"0.8\"/>\n";
        // Labels go left of points in the right third so they stay inside the plot.
        bool leftSide = x > left + pw * 0.66;
        if (!p.label.empty())
            svg += text(leftSide ? x - 10 : x + 10, y - 8, p.label, leftSide ? "end" : "start", 12);
    }
    return svg + "</svg>\n";
}

namespace {

// The largest finite value of every series (at least a tiny positive number).
double seriesMax(const std::vector<Series>& series) {
    double hi = 1e-12;
    for (const Series& s : series)
        for (double v : s.y)
            if (std::isfinite(v)) hi = std::max(hi, v);
    return hi;
}

// A "nice" round axis top above `hi`: 1, 2 or 5 x 10^k.
double niceTop(double hi) {
    const double p = std::pow(10.0, std::floor(std::log10(hi)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= hi) return m * p;
    return 10.0 * p;
}

std::string polyline(const std::vector<std::pair<double, double>>& pts, const char* colour) {
    if (pts.size() < 2) return "";
    std::string d = "<polyline fill=\"none\" stroke=\"" + std::string(colour) +
                    "\" stroke-width=\"1.5\" points=\"";
    for (const auto& [x, y] : pts)
        d += num(x) + "," + num(y) + " ";
    return d + "\"/>\n";
}

} // namespace

std::string seriesPlotSvg(const std::vector<Series>& series, const std::string& xLabel,
                          const std::string& yLabel, const std::vector<double>& marks, int width,
                          int height) {
    const double left = 64, right = 170, top = 16, bottom = 44;
    const double w = width - left - right, h = height - top - bottom;
    size_t n = 1;
    for (const Series& s : series)
        n = std::max(n, s.y.size());
    const double yTop = niceTop(seriesMax(series));
    auto px = [&](double x) { return left + (n > 1 ? x / double(n - 1) : 0.5) * w; };
    auto py = [&](double y) { return top + h - std::clamp(y / yTop, 0.0, 1.0) * h; };
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                      std::to_string(width) + "\" height=\"" + std::to_string(height) +
                      "\" font-family=\"sans-serif\">\n";
    for (int t = 0; t <= 4; ++t) { // y grid: 0, 1/4 .. the top
        const double v = yTop * t / 4.0;
        svg += line(left, py(v), left + w, py(v), "#ddd");
        svg += text(left - 6, py(v) + 4, formatNumber(v), "end", 11);
    }
    for (double m : marks)
        svg += "<line x1=\"" + num(px(m)) + "\" y1=\"" + num(top) + "\" x2=\"" + num(px(m)) +
               "\" y2=\"" + num(top + h) + "\" stroke=\"#999\" stroke-dasharray=\"4 3\"/>\n";
    for (size_t si = 0; si < series.size(); ++si) {
        const Series& s = series[si];
        const char* colour = paletteHex(s.colour >= 0 ? s.colour : int(si));
        std::vector<std::pair<double, double>> run;
        for (size_t x = 0; x <= s.y.size(); ++x) {
            if (x < s.y.size() && std::isfinite(s.y[x])) {
                run.push_back({px(double(x)), py(s.y[x])});
                continue;
            }
            svg += polyline(run, colour);
            run.clear();
        }
        svg += "<rect x=\"" + num(left + w + 12) + "\" y=\"" + num(top + 16.0 * double(si)) +
               "\" width=\"10\" height=\"10\" fill=\"" + colour + "\"/>\n";
        svg += text(left + w + 26, top + 16.0 * double(si) + 9, s.name, "start", 11);
    }
    svg += line(left, top + h, left + w, top + h, "#333");
    svg += line(left, top, left, top + h, "#333");
    for (size_t x : {size_t(0), (n - 1) / 2, n - 1})
        svg += text(px(double(x)), top + h + 14, std::to_string(x), "middle", 11);
    svg += text(left + w / 2, height - 8, xLabel, "middle");
    svg += text(14, top + h / 2, yLabel, "middle", 12,
                (" transform=\"rotate(-90 14 " + num(top + h / 2) + ")\"").c_str());
    return svg + "</svg>\n";
}

} // namespace tp::cli
