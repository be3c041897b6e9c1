// One colour per pipeline on every page (core/renderer/pipeline_colour.h): each registered
// renderer has its own palette index, the report's bar groups and the sweep's series draw a
// pipeline with the same colour, and series of one pipeline are told apart by dashes.
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "compare/report/svg_plot.h"
#include "core/renderer/renderer.h"

namespace tp {
namespace {

std::set<std::string> fills(const std::string& svg) {
    std::set<std::string> out;
    const std::regex fill("fill=\"(#[0-9a-f]{6})\"");
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), fill); it != std::sregex_iterator();
         ++it)
        out.insert((*it)[1]);
    return out;
}

TEST(PipelineColour, EachRendererHasItsOwnAndEveryPageUsesIt) {
    std::set<int> seen;
    for (const RendererEntry& e : registeredRenderers()) {
        const int c = pipelineColour(e.name);
        EXPECT_GE(c, 0) << e.name;
        EXPECT_TRUE(seen.insert(c).second) << e.name << " shares a colour";
    }
    EXPECT_EQ(pipelineColour("no such pipeline"), -1);
    const std::string name = registeredRenderers().back().name;
    const int c = pipelineColour(name);
    const std::string bars = cli::barChartSvg({{name, {{"frame", 2.0}}, c}}, "ms");
    const std::string plot = cli::scatterLogLogSvg(
        {{"", 1, 1, 0}, {"", 2, 2, 0}, {"", 1, 3, 1}, {"", 2, 4, 1}}, "x", "y", 720, 440,
        {name + " 1x", name + " 4x"}, true, {c, c});
    ASSERT_EQ(fills(bars).size(), 1u);
    std::set<std::string> points = fills(plot);
    points.erase("#fafafa"); // the plot area's background
    EXPECT_EQ(points, fills(bars)) << "both series in the bar's colour";
    // The second series of the same pipeline: its line dashed, the first solid.
    EXPECT_NE(plot.find("stroke-dasharray"), std::string::npos);
}

} // namespace
} // namespace tp
