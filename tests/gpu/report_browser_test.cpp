// report.html in a real browser: headless Chromium (Debian's `chromium`) loads the page that
// a small `triptych compare` wrote, offline, and takes a screenshot; the screenshot must show
// the page rendered: the rendered images (many distinct colours), the heat maps (their legend
// ends in inferno's pale yellow) and the SVG plot and bars (the chart palette's colours).
// Chromium is heavy and not in the README's test install list: without it the test skips.
#include <cstdlib>
#include <filesystem>
#include <set>

#include <gtest/gtest.h>
#include <stb_image.h> // Debian's libstb exports stbi_load
#include <unistd.h>

#include "compare/compare.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;

struct Rgb {
    int r, g, b;
};

bool near(const unsigned char* px, Rgb c, int tolerance) {
    return std::abs(px[0] - c.r) <= tolerance && std::abs(px[1] - c.g) <= tolerance && std::abs(px[2] - c.b) <= tolerance;
}

std::string chromium() {
    for (const char* name : {"chromium", "chromium-browser"})
        if (std::system(("command -v " + std::string(name) + " >/dev/null 2>&1").c_str()) == 0) return name;
    return "";
}

} // namespace

TEST(ReportBrowser, ChromiumRendersImagesAndPlots) {
    const std::string browser = chromium();
    if (browser.empty()) GTEST_SKIP() << "chromium not on PATH: report.html not checked in a browser";
    const fs::path dir = fs::temp_directory_path() / ("triptych_browser_" + std::to_string(getpid()));
    fs::remove_all(dir);
    cli::CompareOptions o;
    o.scene.scene = "builtin:courtyard-small";
    o.scene.lightCount = 8;
    o.view.resolution = "96x54";
    o.frames = 1;
    o.warmup = 0;
    o.out = (dir / "out").string();
    ASSERT_EQ(cli::runCompare(o), 0);

    const int width = 1200, height = 3000;
    const std::string shot = (dir / "shot.png").string();
    // No network, a throw-away profile; root in a container needs --no-sandbox.
    const std::string command = "timeout 180 " + browser +
                                " --headless --no-sandbox --disable-gpu --hide-scrollbars --no-first-run"
                                " --user-data-dir='" + (dir / "profile").string() + "' --window-size=" +
                                std::to_string(width) + "," + std::to_string(height) + " --screenshot='" + shot +
                                "' 'file://" + o.out + "/report.html' >'" + (dir / "chromium.log").string() + "' 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;

    int w = 0, h = 0, n = 0;
    unsigned char* pixels = stbi_load(shot.c_str(), &w, &h, &n, 3);
    ASSERT_NE(pixels, nullptr) << "screenshot does not decode: " << stbi_failure_reason();
    EXPECT_EQ(w, width);
    EXPECT_EQ(h, height);
    size_t notBackground = 0, paleYellow = 0;
    std::set<int> colours;
    // The chart palette (compare/svg_plot.cpp): the reference, then the first three pipelines.
    const Rgb palette[] = {{0x1f, 0x77, 0xb4}, {0xd6, 0x27, 0x28}, {0x2c, 0xa0, 0x2c}, {0x94, 0x67, 0xbd}};
    size_t paletteHits[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < size_t(w) * size_t(h); ++i) {
        const unsigned char* px = pixels + i * 3;
        notBackground += !(px[0] > 240 && px[1] > 240 && px[2] > 240);
        paleYellow += near(px, {0xfc, 0xff, 0xa4}, 16); // the top of the heat-map legend
        colours.insert((px[0] >> 3) << 10 | (px[1] >> 3) << 5 | (px[2] >> 3));
        for (int c = 0; c < 4; ++c) paletteHits[c] += near(px, palette[c], 6);
    }
    stbi_image_free(pixels);
    SCOPED_TRACE("screenshot " + shot);
    // A blank or error page is nearly all one colour; this page is mostly images and charts.
    EXPECT_GT(double(notBackground) / (double(w) * h), 0.2);
    EXPECT_GT(colours.size(), 500u) << "rendered images bring hundreds of distinct colours";
    EXPECT_GT(paleYellow, 200u) << "heat-map legends";
    for (int c = 0; c < 4; ++c) EXPECT_GT(paletteHits[c], 30u) << "plot/bar colour " << c;
    if (!HasFailure()) fs::remove_all(dir);
}

} // namespace tp::test
