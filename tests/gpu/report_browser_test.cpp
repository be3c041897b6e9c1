// report.html in a real browser: headless Chromium (Debian's `chromium`) loads the page that
// a small `triptych compare` wrote, offline, and takes a screenshot; the screenshot must show
// the page rendered: the rendered images (many distinct colours), the heat maps (their legend
// ends in inferno's pale yellow) and the SVG plot and bars (the chart palette's colours).
// Then the page's script, driven by synthetic events in the same browser: flip (click, F) and
// the loupe (shown at the hovered pixel, whole pixels magnified, hidden on leave).
// The README's test command installs chromium; without it on PATH the test skips.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>
#include <stb_image.h> // Debian's libstb exports stbi_load
#include <unistd.h>

#include "compare/commands/compare.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;

struct Rgb {
    int r, g, b;
};

bool near(const unsigned char* px, Rgb c, int tolerance) {
    return std::abs(px[0] - c.r) <= tolerance && std::abs(px[1] - c.g) <= tolerance &&
           std::abs(px[2] - c.b) <= tolerance;
}

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Runs after the page has loaded: drives report.html's flip and loupe with synthetic events
// and writes one PASS/FAIL line per check into <pre id="checks">, which --dump-dom prints.
const char* kChecks = R"(<pre id="checks">not run</pre><script>
window.addEventListener('load',function(){
var out=[];
function check(name,ok){out.push((ok?'PASS ':'FAIL ')+name);}
function same(a,b){return a[0]===b[0]&&a[1]===b[1]&&a[2]===b[2];}
try{
  var ref=document.getElementById('img-reference'),img=document.querySelector('img.flip');
  check('reference and pipeline images are marked',!!ref&&!!img);
  var own=img.getAttribute('src');
  check('a pipeline image is not the reference',own!==ref.getAttribute('src'));
  img.dispatchEvent(new MouseEvent('click',{bubbles:true}));
  check('click shows the reference',img.getAttribute('src')===ref.getAttribute('src')&&img.dataset.showing==='reference');
  check('the caption says so',/reference/.test(img.parentNode.querySelector('.flip-state').textContent));
  // The centre of image pixel (30, 20): several screen pixels wide, so rounding of the event's
  // coordinates cannot move it to a neighbour.
  var r=img.getBoundingClientRect(),px=30,py=20;
  img.dispatchEvent(new MouseEvent('mousemove',{bubbles:true,clientX:r.left+(px+0.5)*r.width/img.naturalWidth,
                                                clientY:r.top+(py+0.5)*r.height/img.naturalHeight}));
  document.dispatchEvent(new KeyboardEvent('keydown',{key:'f',ctrlKey:true,bubbles:true}));
  check('Ctrl+F (find) does not flip',img.dataset.showing==='reference');
  document.dispatchEvent(new KeyboardEvent('keydown',{key:'f',bubbles:true}));
  check('F over the image flips it back',img.getAttribute('src')===own&&img.dataset.showing==='pipeline');
  var loupe=document.getElementById('loupe');
  check('the loupe shows on hover',!!loupe&&getComputedStyle(loupe).display==='block');
  var x=+loupe.dataset.x,y=+loupe.dataset.y;
  check('the loupe is at the hovered pixel (got '+x+', '+y+')',x===px&&y===py);
  var c=document.createElement('canvas');c.width=img.naturalWidth;c.height=img.naturalHeight;
  var cc=c.getContext('2d');cc.drawImage(img,0,0);
  var lc=loupe.querySelector('canvas'),l=lc.getContext('2d');
  var Z=8,H=(lc.width/Z-1)/2;
  check('the loupe centre is the hovered pixel',same(l.getImageData(H*Z+4,H*Z+4,1,1).data,cc.getImageData(x,y,1,1).data));
  var a=l.getImageData((H+1)*Z+1,H*Z+1,1,1).data,b=l.getImageData((H+1)*Z+6,H*Z+6,1,1).data;
  check('the loupe magnifies whole pixels',same(a,b)&&same(a,cc.getImageData(x+1,y,1,1).data));
  var far=l.getImageData(1,1,1,1).data;
  check('the loupe shows the neighbourhood',same(far,cc.getImageData(x-H,y-H,1,1).data));
  img.dispatchEvent(new MouseEvent('mouseleave',{}));
  check('the loupe hides on leave',getComputedStyle(loupe).display==='none');
  document.dispatchEvent(new KeyboardEvent('keydown',{key:'F',bubbles:true}));
  var all=document.querySelectorAll('img.flip'),flipped=0;
  all.forEach(function(i){flipped+=i.dataset.showing==='reference';});
  check('F elsewhere flips every pipeline image',all.length>0&&flipped===all.length);
}catch(e){out.push('FAIL exception '+e);}
document.getElementById('checks').textContent=out.join('\n');
});
</script>
)";

std::string chromium() {
    for (const char* name : {"chromium", "chromium-browser"})
        if (std::system(("command -v " + std::string(name) + " >/dev/null 2>&1").c_str()) == 0)
            return name;
    return "";
}

} // namespace

TEST(ReportBrowser, ChromiumRendersImagesAndPlots) {
    const std::string browser = chromium();
    if (browser.empty())
        GTEST_SKIP() << "chromium not on PATH: report.html not checked in a browser";
    const fs::path dir =
        fs::temp_directory_path() / ("triptych_browser_" + std::to_string(getpid()));
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
    // Root in a container needs --no-sandbox; a small /dev/shm, --disable-dev-shm-usage.
    const std::string browserCommand =
        "timeout 120 " + browser +
        " --headless --no-sandbox --disable-gpu --disable-dev-shm-usage"
        " --hide-scrollbars --no-first-run --user-data-dir='" +
        (dir / "profile").string() + "' --window-size=" + std::to_string(width) + "," +
        std::to_string(height);
    const std::string command = browserCommand + " --screenshot='" + shot + "' 'file://" + o.out +
                                "/report.html' >'" + (dir / "chromium.log").string() + "' 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;

    int w = 0, h = 0, n = 0;
    unsigned char* pixels = stbi_load(shot.c_str(), &w, &h, &n, 3);
    ASSERT_NE(pixels, nullptr) << "screenshot does not decode: " << stbi_failure_reason();
    EXPECT_EQ(w, width);
    EXPECT_EQ(h, height);
    size_t notBackground = 0, paleYellow = 0;
    std::set<int> colours;
    // The chart palette (compare/report/svg_plot.cpp): the reference, then the first three pipelines.
    const Rgb palette[] = {
        {0x1f, 0x77, 0xb4}, {0xd6, 0x27, 0x28}, {0x2c, 0xa0, 0x2c}, {0x94, 0x67, 0xbd}};
    size_t paletteHits[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < size_t(w) * size_t(h); ++i) {
        const unsigned char* px = pixels + i * 3;
        notBackground += !(px[0] > 240 && px[1] > 240 && px[2] > 240);
        paleYellow += near(px, {0xfc, 0xff, 0xa4}, 16); // the top of the heat-map legend
        colours.insert((px[0] >> 3) << 10 | (px[1] >> 3) << 5 | (px[2] >> 3));
        for (int c = 0; c < 4; ++c)
            paletteHits[c] += near(px, palette[c], 6);
    }
    stbi_image_free(pixels);
    SCOPED_TRACE("screenshot " + shot);
    // A blank or error page is nearly all one colour; this page is mostly images and charts.
    EXPECT_GT(double(notBackground) / (double(w) * h), 0.2);
    EXPECT_GT(colours.size(), 500u) << "rendered images bring hundreds of distinct colours";
    EXPECT_GT(paleYellow, 200u) << "heat-map legends";
    for (int c = 0; c < 4; ++c)
        EXPECT_GT(paletteHits[c], 30u) << "plot/bar colour " << c;

    // The same page with the checks appended (the page itself carries no test code).
    std::string page = readText(o.out + "/report.html");
    const size_t end = page.rfind("</body>");
    ASSERT_NE(end, std::string::npos);
    page.insert(end, kChecks);
    const fs::path checked = dir / "out" / "report_checked.html";
    std::ofstream(checked, std::ios::binary) << page;
    const fs::path dom = dir / "dom.html";
    const std::string dump = browserCommand + " --virtual-time-budget=10000 --dump-dom 'file://" +
                             checked.string() + "' >'" + dom.string() + "' 2>'" +
                             (dir / "chromium_dom.log").string() + "'";
    ASSERT_EQ(std::system(dump.c_str()), 0) << dump;
    const std::string text = readText(dom);
    const size_t from = text.find("<pre id=\"checks\">"), to = text.find("</pre>", from);
    ASSERT_NE(from, std::string::npos) << "no checks in the dumped page " << dom;
    const std::string results = text.substr(from, to - from);
    std::istringstream lines(results);
    size_t passed = 0;
    for (std::string line; std::getline(lines, line);) {
        EXPECT_EQ(line.find("FAIL"), std::string::npos) << line;
        passed += line.find("PASS ") != std::string::npos;
    }
    EXPECT_EQ(passed, 13u) << results;
    if (!HasFailure()) fs::remove_all(dir);
}

} // namespace tp::test
