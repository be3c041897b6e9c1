#pragma once
// Inline SVG charts for the offline report pages: horizontal bars and a labelled scatter
// plot with logarithmic axes. Plain strings, no script, no external font or stylesheet.
#include <string>
#include <vector>

#include "core/renderer/pipeline_colour.h"
#include "core/renderer/pipeline_colour.h" // pipelineColour: a series' palette index
#include "core/util/number_text.h"     // formatNumber, the plots' and pages' numbers

namespace tp::cli {

struct BarGroup {
    std::string title;                                // e.g. the pipeline
    std::vector<std::pair<std::string, double>> bars; // label, value
    int colour = -1;                                  // palette index; -1: the group's index
};

// One bar per value on a shared linear scale (0 .. largest value), grouped under titles;
// each bar is labelled on the left and its value (with `unit`) on the right.
std::string barChartSvg(const std::vector<BarGroup>& groups, const std::string& unit,
                        int width = 900);

struct PlotPoint {
    std::string label;   // drawn beside the point; may be empty
    double x = 0, y = 0; // y <= 0 is drawn on the bottom edge, marked "0" (log axis)
    int series = -1;     // series (and, without seriesColours, colour) index; -1: per point
    bool ring = false;   // circled (e.g. on the Pareto front)
    int colour = -1;     // without series: this point's palette index; -1: its index
};

// A line drawn under a scatter plot's points, in data coordinates (e.g. a roofline's roofs),
// labelled at its right end.
struct PlotLine {
    std::vector<std::pair<double, double>> xy;
    std::string label;
    bool dashed = false;
};

// Scatter plot with log x and log y axes, ticks at 1, 2, 5 x 10^k. With seriesNames, points
// of one series share a colour, are joined in x order (joinSeries), and a legend names the series.
// seriesColours: the palette index of each series (series of one pipeline may share one: their
// lines are then told apart by dashes); empty: the series' own index.
std::string scatterLogLogSvg(const std::vector<PlotPoint>& points, const std::string& xLabel,
                             const std::string& yLabel, int width = 720, int height = 440,
                             const std::vector<std::string>& seriesNames = {},
                             bool joinSeries = true, const std::vector<int>& seriesColours = {},
                             const std::vector<PlotLine>& lines = {});

// Values along a run of views (x = 0, 1, 2, ...), one polyline per series, linear axes from 0;
// `marks`: x positions drawn as dashed vertical lines (e.g. where a ranking flips). A series'
// NaN values are gaps.
struct Series {
    std::string name;
    int colour = -1; // palette index; -1: the series' own index
    std::vector<double> y;
};
std::string seriesPlotSvg(const std::vector<Series>& series, const std::string& xLabel,
                          const std::string& yLabel, const std::vector<double>& marks = {},
                          int width = 900, int height = 320);

// Escapes &, <, >, " and ' for HTML/SVG text and attributes.
std::string escapeXml(const std::string& text);

} // namespace tp::cli
