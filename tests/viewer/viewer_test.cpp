// triptych view --headless on the default device (lavapipe) with validation on: scripts drive
// the same UI code a user sees, and the tests check what the screenshots and stats show.
// Small: 160x90 of the small built-in scene, the reference only where a test needs it.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <sys/wait.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/camera/camera_path.h"
#include "core/cli/scene_input.h"
#include "core/gpu/context.h"
#include "core/image/image_io.h"
#include "core/reference/reference_renderer.h"
#include "core/renderer/renderer.h"
#include "viewer/camera_control.h"
#include "viewer/composite.h"
#include "viewer/view_loop.h"

namespace tp::view {
namespace {

constexpr uint32_t kW = 160, kH = 90;

// The first two registered pipelines (never spelled: the registry decides).
std::string pipeline(size_t i) {
    std::vector<std::string> names;
    for (const RendererEntry& e : registeredRenderers())
        if (e.name != kReferenceRenderer) names.push_back(e.name);
    return names.at(std::min(i, names.size() - 1));
}

struct ViewRun {
    int code = -1;
    std::string out;
    ImageRGBA shot(const std::string& name) const {
        Result<ImageRGBA> r = readPng(out + "/" + name);
        EXPECT_TRUE(r) << (r ? "" : r.error());
        return r ? *r : ImageRGBA{};
    }
    nlohmann::json stats(const std::string& name) const {
        std::ifstream in(out + "/" + name);
        return nlohmann::json::parse(in);
    }
};

ViewRun runScript(const std::string& name, const std::string& script, bool reference = false,
                  const std::function<void(LoopSetup&)>& more = {}) {
    ViewRun run;
    run.out = (std::filesystem::temp_directory_path() / ("triptych_view_" + name)).string();
    std::filesystem::remove_all(run.out);
    std::filesystem::create_directories(run.out);
    const std::string path = run.out + "/script.txt";
    std::ofstream(path) << script;
    LoopSetup setup;
    Result<std::vector<ScriptLine>> lines = readScript(path);
    EXPECT_TRUE(lines) << (lines ? "" : lines.error());
    if (!lines) return run;
    setup.script = *lines;
    setup.scriptPath = path;
    setup.out = run.out;
    setup.waitLimitSeconds = 120;
    ViewState& s = setup.viewer.initial;
    s.scene.scene = "builtin:courtyard-small";
    s.scene.lightCount = 16;
    s.width = kW, s.height = kH;
    s.pipelineA = pipeline(0);
    s.pipelineB = pipeline(1);
    s.reference = reference;
    setup.viewer.context.validate = true;
    setup.viewer.exe = TP_TRIPTYCH_EXE;
    if (more) more(setup);
    run.code = runHeadless(setup);
    return run;
}

bool isDivider(const ImageRGBA& img, uint32_t x, uint32_t y) {
    const float* p = img.at(x, y);
    return std::lround(p[0] * 255) == kDividerRgb[0] && std::lround(p[1] * 255) == kDividerRgb[1] &&
           std::lround(p[2] * 255) == kDividerRgb[2];
}

uint32_t dividerRows(const ImageRGBA& img, uint32_t x) {
    uint32_t n = 0;
    for (uint32_t y = 0; y < kH; ++y)
        n += isDivider(img, x, y);
    return n;
}

TEST(Viewer, SplitLineSitsWhereTheScriptAndTheDragPutIt) {
    ViewRun r =
        runScript("split", "split 0.25\nwait\nscreenshot split.png\nstats split.json\n"
                           "drag 40 45 120 45\nwait\nscreenshot dragged.png\nstats dragged.json\n");
    ASSERT_EQ(r.code, 0);
    ImageRGBA shot = r.shot("split.png");
    ASSERT_GE(shot.width, kW + 300); // the scene area and the panel beside it
    EXPECT_EQ(dividerRows(shot, 40), kH) << "the divider at 0.25 of 160 pixels is column 40";
    for (uint32_t x : {0u, 39u, 41u, 100u})
        EXPECT_EQ(dividerRows(shot, x), 0u) << "column " << x;
    // The UI is in the screenshot: the panel right of the scene area is not one flat colour.
    const float* a = shot.at(kW + 40, 8);
    bool varied = false;
    for (uint32_t y = 0; y < 200 && !varied; ++y)
        for (uint32_t x = kW + 1; x < shot.width; x += 3)
            varied |= shot.at(x, y)[0] != a[0];
    EXPECT_TRUE(varied);
    EXPECT_EQ(r.stats("split.json")["split_column"], 40);
    ImageRGBA dragged = r.shot("dragged.png");
    EXPECT_EQ(dividerRows(dragged, 120), kH) << "dragged from column 40 to 120";
    EXPECT_EQ(dividerRows(dragged, 40), 0u);
    EXPECT_EQ(r.stats("dragged.json")["split_column"], 120);
}

TEST(Viewer, DifferenceOfAPipelineAgainstItselfIsZero) {
    ViewRun r = runScript("diff_self", "pipeline b " + pipeline(0) +
                                           "\nmode difference\nwait\nscreenshot diff.png\n"
                                           "stats diff.json\n");
    ASSERT_EQ(r.code, 0);
    ImageRGBA shot = r.shot("diff.png");
    nlohmann::json stats = r.stats("diff.json");
    // compare's rule: a scale of 0 becomes 1e-6 (the legend needs a non-zero end).
    EXPECT_FLOAT_EQ(stats["difference_scale"].get<float>(), 1e-6f);
    // Every pixel of the map is the colour of 0: the first pixel's, and not the divider's.
    const float* zero = shot.at(0, 0);
    uint32_t other = 0;
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x)
            for (int c = 0; c < 3; ++c)
                other += shot.at(x, y)[c] != zero[c];
    EXPECT_EQ(other, 0u);
    EXPECT_FALSE(isDivider(shot, 0, 0));
}

TEST(Viewer, DifferenceOfTwoPipelinesIsNotBlank) {
    if (pipeline(0) == pipeline(1)) GTEST_SKIP() << "one pipeline registered";
    ViewRun r = runScript("diff_two", "mode difference\nwait\nstats diff.json\n");
    ASSERT_EQ(r.code, 0);
    EXPECT_GT(r.stats("diff.json")["difference_scale"].get<float>(), 1e-6f);
}

TEST(Viewer, FlipShowsBWhereAWas) {
    if (pipeline(0) == pipeline(1)) GTEST_SKIP() << "one pipeline registered";
    // A fixed exposure (auto exposure follows A's image), and one render of each pipeline:
    // split 0 shows B whole, from the same render the flip shows.
    ViewRun r =
        runScript("flip", "exposure 0\nsplit 1\nwait\nscreenshot a.png\nkey f\nwait\n"
                          "screenshot flipped.png\nflip off\nsplit 0\nwait\nscreenshot b.png\n");
    ASSERT_EQ(r.code, 0);
    ImageRGBA a = r.shot("a.png"), flipped = r.shot("flipped.png"), b = r.shot("b.png");
    auto sceneDiffers = [](const ImageRGBA& x, const ImageRGBA& y) {
        uint32_t n = 0;
        for (uint32_t row = 0; row < kH; ++row)
            for (uint32_t col = 0; col < kW; ++col)
                for (int c = 0; c < 3; ++c)
                    n += x.at(col, row)[c] != y.at(col, row)[c];
        return n;
    };
    EXPECT_EQ(sceneDiffers(flipped, b), 0u) << "flip shows B over the whole split-at-1 view";
    EXPECT_GT(sceneDiffers(a, flipped), 0u) << "the two pipelines' images differ somewhere";
}

// --share-device on renders on the UI's device and composes the images where they are
// (lavapipe: its one queue, shared); off renders on a device of its own and uploads the
// read-back images. The same GPU composite of the same floats: the same bytes, split and
// difference, and with sharing no image is read back until the inspector asks for pixels.
TEST(Viewer, ASharedDeviceShowsTheSameImagesWithoutReadingThemBack) {
    const std::string script = "exposure 0\nwait\nscreenshot split.png\nstats split.json\n"
                               "mode difference\nwait\nscreenshot diff.png\nstats diff.json\n"
                               "mode split\nhover 100 50\nwait\nstats hover.json\n";
    auto shared = [](const char* mode) {
        return [mode](LoopSetup& s) { s.viewer.shareDevice = mode; };
    };
    ViewRun on = runScript("share_on", script, false, shared("on"));
    ViewRun off = runScript("share_off", script, false, shared("off"));
    ASSERT_EQ(on.code, 0);
    ASSERT_EQ(off.code, 0);
    EXPECT_TRUE(on.stats("split.json")["shares_device"].get<bool>());
    EXPECT_FALSE(off.stats("split.json")["shares_device"].get<bool>());
    EXPECT_EQ(on.stats("diff.json")["image_readbacks"], 0) << "shown without a readback";
    EXPECT_EQ(on.stats("diff.json")["difference_scale"], off.stats("diff.json")["difference_scale"]);
    for (const char* shot : {"split.png", "diff.png"}) {
        ImageRGBA x = on.shot(shot), y = off.shot(shot);
        ASSERT_EQ(x.width, y.width);
        uint32_t differing = 0;
        for (uint32_t row = 0; row < kH; ++row)
            for (uint32_t col = 0; col < kW; ++col)
                for (int c = 0; c < 3; ++c)
                    differing += x.at(col, row)[c] != y.at(col, row)[c];
        EXPECT_EQ(differing, 0u) << shot;
    }
    // The inspector reads pixels: they come back for it, the same values as without sharing.
    nlohmann::json hover = on.stats("hover.json");
    EXPECT_GE(hover["image_readbacks"].get<int>(), 1);
    ASSERT_TRUE(hover.contains("inspection"));
    EXPECT_EQ(hover["inspection"]["a"], off.stats("hover.json")["inspection"]["a"]);
}

TEST(Viewer, InspectorReadsThePixelUnderTheCursor) {
    ViewRun r = runScript("hover", "pipeline b " + pipeline(0) +
                                       "\nwait\nhover 100 50\nstats hover.json\n"
                                       "screenshot hover.png\n");
    ASSERT_EQ(r.code, 0);
    nlohmann::json s = r.stats("hover.json");
    ASSERT_TRUE(s.contains("inspection"));
    EXPECT_EQ(s["inspection"]["x"], 100);
    EXPECT_EQ(s["inspection"]["y"], 50);
    EXPECT_EQ(s["inspection"]["a"], s["inspection"]["b"]); // one pipeline on both sides
    double sum = 0;
    for (double v : s["inspection"]["a"])
        sum += v;
    EXPECT_GT(sum, 0.0) << "a lit courtyard pixel";
}

TEST(Viewer, InspectorListsTheLightsReachingTheSurface) {
    // Directional lights reach every surface and no sky: the list is all of them or empty.
    ViewRun r = runScript("pixel_lights",
                          "pipeline b " + pipeline(0) +
                              "\nlights types directional\nlights count 3\n"
                              "wait\nhover 80 85\nstats floor.json\nhover 80 0\nstats sky.json\n");
    ASSERT_EQ(r.code, 0);
    nlohmann::json floor = r.stats("floor.json")["inspection"],
                   sky = r.stats("sky.json")["inspection"];
    EXPECT_TRUE(floor["surface"].get<bool>());
    EXPECT_EQ(floor["lights"], nlohmann::json::array({0, 1, 2}));
    EXPECT_FALSE(sky["surface"].get<bool>());
    EXPECT_TRUE(sky["lights"].empty());
}

TEST(Viewer, ReferenceInTheBackgroundIsMarkedStaleWhenTheViewMoves) {
    ViewRun r = runScript("reference",
                          "wait\nstats fresh.json\ncamera orbit 20 0\nframes 1\nstats moved.json\n"
                          "wait\nstats again.json\n",
                          /*reference=*/true);
    ASSERT_EQ(r.code, 0);
    nlohmann::json fresh = r.stats("fresh.json"), moved = r.stats("moved.json"),
                   again = r.stats("again.json");
    EXPECT_FALSE(fresh["reference_stale"].get<bool>());
    ASSERT_TRUE(fresh.contains("a_vs_reference"));
    EXPECT_GT(fresh["a_vs_reference"]["psnr"].get<double>(), 20.0);
    EXPECT_TRUE(moved["reference_stale"].get<bool>());
    EXPECT_FALSE(moved.contains("a_vs_reference")) << "no metric against another view's reference";
    EXPECT_FALSE(again["reference_stale"].get<bool>());
    EXPECT_NE(fresh["camera"]["position"], again["camera"]["position"]);
}

TEST(Viewer, ASceneThatFailsToLoadKeepsTheViewerOpenWithTheError) {
    ViewRun r = runScript(
        "bad_scene", "scene /nonexistent/scene.gltf\nwait\nexpect-error nonexistent\n"
                     "screenshot error.png\nscene builtin:courtyard-small\nwait\nstats ok.json\n");
    ASSERT_EQ(r.code, 0);
    EXPECT_EQ(r.stats("ok.json")["error"], "");
}

TEST(Viewer, OverlayShowsADebugImageOfA) {
    ViewRun r =
        runScript("overlay", "mode overlay\nwait\nstats overlay.json\nscreenshot overlay.png\n");
    ASSERT_EQ(r.code, 0);
    nlohmann::json s = r.stats("overlay.json");
    EXPECT_FALSE(s["pipeline_a"]["debug_images"].empty());
}

TEST(Viewer, ABookmarkBringsTheCameraBack) {
    ViewRun r =
        runScript("bookmark", "pipeline b " + pipeline(0) +
                                  "\ncamera orbit 30 10\ncamera save b.json\n"
                                  "wait\nstats saved.json\ncamera reset\nwait\nstats reset.json\n"
                                  "camera load b.json\nwait\nstats loaded.json\n");
    ASSERT_EQ(r.code, 0);
    nlohmann::json saved = r.stats("saved.json"), reset = r.stats("reset.json"),
                   loaded = r.stats("loaded.json");
    EXPECT_NE(saved["camera"], reset["camera"]);
    for (const char* k : {"position", "target"})
        for (int i = 0; i < 3; ++i)
            EXPECT_NEAR(saved["camera"][k][i].get<double>(), loaded["camera"][k][i].get<double>(),
                        1e-5)
                << k;
}

// A path recorded by flying: each key is the camera when it was added, the file reads back
// through --camera-path's reader with the keys at the ends; and a camera move is followed by
// the kept renderers (stats: "planned" false after the first render of a pipeline).
TEST(Viewer, APathRecordedByFlyingReadsBackThroughItsKeys) {
    ViewRun r = runScript("path", "pipeline b " + pipeline(0) +
                                      "\nwait\ncamera key\nstats k0.json\ncamera orbit 40 5\n"
                                      "wait\ncamera key\nstats k1.json\ncamera path p.json\n");
    ASSERT_EQ(r.code, 0);
    Result<std::vector<Camera>> views = readCameraPath(r.out + "/p.json");
    ASSERT_TRUE(views) << views.error();
    ASSERT_EQ(views->size(), 31u); // 30 views per segment, and the last key
    for (auto [file, view] : {std::pair{"k0.json", views->front()}, {"k1.json", views->back()}}) {
        nlohmann::json key = r.stats(file)["camera"];
        for (int i = 0; i < 3; ++i)
            EXPECT_NEAR(key["position"][i].get<double>(), view.position[i], 1e-4) << file;
    }
    EXPECT_FALSE(r.stats("k1.json")["pipeline_a"]["planned"].get<bool>()) << "the camera move replanned";
}

TEST(Viewer, ExportWritesRenderAndCompareOfTheCurrentView) {
    ViewRun r = runScript("export", "pipeline b " + pipeline(0) +
                                        "\ncamera orbit 15 0\nwait\nstats view.json\n"
                                        "export exported\n");
    ASSERT_EQ(r.code, 0);
    const std::string dir = r.out + "/exported";
    EXPECT_TRUE(std::filesystem::exists(dir + "/render/" + pipeline(0) + ".png"));
    EXPECT_TRUE(std::filesystem::exists(dir + "/render/render.json"));
    EXPECT_TRUE(std::filesystem::exists(dir + "/compare/report.html"));
    // The moved camera, not the scene's: what the commands used is what the viewer showed.
    nlohmann::json view = r.stats("view.json");
    std::ifstream in(dir + "/render/camera.json");
    nlohmann::json used = nlohmann::json::parse(in);
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(used["position"][i].get<double>(), view["camera"]["position"][i].get<double>(),
                    1e-5);
}

TEST(Viewer, AnMsaaCountTheDeviceLacksIsRefusedWithTheReason) {
    // lavapipe has 1x and 4x; 8x is refused (the panel greys it out with the same reason).
    Result<std::unique_ptr<GpuContext>> ctx = GpuContext::create({});
    ASSERT_TRUE(ctx);
    const uint32_t counts = (*ctx)->caps.colorSampleCounts;
    ctx->reset();
    if (!(counts & 4) || (counts & 8)) GTEST_SKIP() << "the device does not have 4x without 8x";
    ViewRun ok = runScript("msaa4", "msaa 4\nwait\nstats four.json\n");
    ASSERT_EQ(ok.code, 0);
    EXPECT_EQ(ok.stats("four.json")["error"], "");
    ViewRun refused = runScript("msaa8", "wait\nmsaa 8\nwait\n");
    EXPECT_EQ(refused.code, 2);
}

TEST(Viewer, ABadScriptLineIsOneErrorAndNoRun) {
    const std::string path =
        (std::filesystem::temp_directory_path() / "triptych_view_bad.txt").string();
    std::ofstream(path) << "split 0.5\nteleport 1 2\n";
    Result<std::vector<ScriptLine>> lines = readScript(path);
    ASSERT_FALSE(lines);
    EXPECT_NE(lines.error().find(":2: unknown command 'teleport'"), std::string::npos)
        << lines.error();
}

// Every reading error is "PATH:LINE: message", or "PATH: message" for the file as a whole; a
// directory is refused (it read as an empty script and ran nothing).
TEST(Viewer, MalformedScriptsSayPathAndLine) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "triptych_view_malformed";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    auto error = [&](const std::string& name, const std::string& text) {
        const std::string path = (dir / name).string();
        std::ofstream(path) << text;
        Result<std::vector<ScriptLine>> lines = readScript(path);
        return lines ? std::string("(read)") : lines.error();
    };
    const std::string p = dir.string() + "/";
    EXPECT_EQ(error("unknown.txt", "# a comment\n\nwait\nteleport 1 2\n"),
              p + "unknown.txt:4: unknown command 'teleport'");
    EXPECT_EQ(error("few.txt", "split\n"), p + "few.txt:1: expected 'split SHARE (0 to 1)'");
    EXPECT_EQ(error("many.txt", "wait\nwait now # comment\n"), p + "many.txt:2: expected 'wait'");
    EXPECT_EQ(error("control.txt", "frames 1\nfo\x01o\n"),
              p + "control.txt:2: unknown command 'fo o'");
    Result<std::vector<ScriptLine>> missing = readScript(p + "missing.txt");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error(), p + "missing.txt: cannot open the file");
    Result<std::vector<ScriptLine>> folder = readScript(dir.string());
    ASSERT_FALSE(folder);
    EXPECT_EQ(folder.error(), dir.string() + ": is a directory, not a script");
    std::filesystem::remove_all(dir);
}

// --- Playing a camera path and moving lights (docs/viewer.md, "Playing a path") ---

namespace pathtest {

// A path of `frames` views over courtyard-small, linear from the scene's camera to the camera
// orbited 40 degrees and pitched: every view differs from the one before.
std::vector<Camera> writePath(const std::string& file, uint32_t frames) {
    cli::SceneOptions o;
    o.scene = "builtin:courtyard-small";
    o.lightCount = 0;
    const Camera start = cli::loadScene(o).camera;
    Camera end = start;
    orbit(end, 40.0f, 10.0f);
    Status written = writeCameraPath(file, {start, end}, frames, Interpolation::Linear);
    EXPECT_TRUE(written) << (written ? "" : written.error());
    Result<std::vector<Camera>> views = readCameraPath(file);
    EXPECT_TRUE(views) << (views ? "" : views.error());
    return views ? *views : std::vector<Camera>{};
}

// The setup --camera-path gives: the views, playing from view 0 (or paused).
std::function<void(LoopSetup&)> playing(const std::vector<Camera>& views, bool play) {
    return [views, play](LoopSetup& setup) {
        setup.viewer.path.views = views;
        setup.viewer.path.frames = uint32_t(views.size());
        setup.viewer.path.source = "test path";
        setup.viewer.path.playing = play;
    };
}

std::string pathFile(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("triptych_view_" + name + ".json")).string();
}

void expectCamera(const nlohmann::json& camera, const Camera& c, const std::string& what) {
    for (int i = 0; i < 3; ++i) {
        EXPECT_FLOAT_EQ(camera["position"][i].get<float>(), c.position[i]) << what;
        EXPECT_FLOAT_EQ(camera["target"][i].get<float>(), c.target[i]) << what;
    }
}

uint32_t sceneAreaDiffers(const ImageRGBA& x, const ImageRGBA& y) {
    uint32_t n = 0;
    for (uint32_t row = 0; row < kH; ++row)
        for (uint32_t col = 0; col < kW; ++col)
            for (int c = 0; c < 3; ++c)
                n += x.at(col, row)[c] != y.at(col, row)[c];
    return n;
}

} // namespace pathtest

// Seeking lands on the view: the state's camera and the camera A rendered with are the path's
// camera of that view, bit for bit, and the two views' images differ.
TEST(ViewerPath, SeekLandsOnTheViewAndItsImage) {
    using namespace pathtest;
    const std::vector<Camera> views = writePath(pathFile("seek"), 4);
    ASSERT_EQ(views.size(), 4u);
    ViewRun r =
        runScript("path_seek",
                  "exposure 0\nsplit 1\npath seek 0\nwait\nstats v0.json\nscreenshot v0.png\n"
                  "path seek 3\nwait\nstats v3.json\nscreenshot v3.png\n",
                  false, playing(views, false));
    ASSERT_EQ(r.code, 0);
    for (auto [file, k] : {std::pair{"v0.json", 0u}, {"v3.json", 3u}}) {
        nlohmann::json s = r.stats(file);
        EXPECT_EQ(s["path"]["frame"], k) << file;
        EXPECT_FALSE(s["path"]["playing"].get<bool>()) << file;
        expectCamera(s["camera"], views[k], file);
        expectCamera(s["pipeline_a"]["camera"], views[k], std::string(file) + " (A's image)");
    }
    EXPECT_GT(sceneAreaDiffers(r.shot("v0.png"), r.shot("v3.png")), 100u)
        << "the camera of view 3 sees another image than view 0's";
}

// Played from view 0, the path runs to its last view and stops there; every view was rendered
// (A's renders count at least the path's views), each followed by the kept renderer; the stats
// carry each side's frames per second and GPU memory.
TEST(ViewerPath, PlayRunsToTheLastViewWithLiveRateAndMemory) {
    using namespace pathtest;
    const std::vector<Camera> views = writePath(pathFile("play"), 5);
    ASSERT_EQ(views.size(), 5u);
    ViewRun r = runScript("path_play", "wait\nstats end.json\n", false, playing(views, true));
    ASSERT_EQ(r.code, 0);
    nlohmann::json s = r.stats("end.json");
    EXPECT_EQ(s["path"]["frame"], 4);
    EXPECT_FALSE(s["path"]["playing"].get<bool>()) << "stopped at the end";
    expectCamera(s["pipeline_a"]["camera"], views[4], "A's last image");
    EXPECT_FALSE(s["pipeline_a"]["planned"].get<bool>()) << "a path view was planned again";
    for (const char* side : {"pipeline_a", "pipeline_b"}) {
        const nlohmann::json& p = s[side];
        ASSERT_TRUE(p.contains("fps")) << side;
        EXPECT_GE(p["fps"]["renders"].get<int>(), 5) << side << ": one render per view";
        EXPECT_GT(p["fps"]["shown"].get<double>(), 0.0) << side;
        EXPECT_GT(p["fps"]["gpu"].get<double>(), p["fps"]["shown"].get<double>())
            << side << ": a render's wall time holds its GPU frame and more";
        EXPECT_NEAR(p["fps"]["gpu"].get<double>() * p["fps"]["gpu_frame_ms_median"].get<double>(),
                    1000.0, 1e-6);
        const nlohmann::json& m = p["gpu_memory_bytes"];
        EXPECT_GT(m["pipeline"].get<uint64_t>(), 0u) << side;
        EXPECT_GT(m["scene"].get<uint64_t>(), 0u) << side;
        EXPECT_EQ(m["total"].get<uint64_t>(),
                  m["pipeline"].get<uint64_t>() + m["scene"].get<uint64_t>());
    }
}

// Pause holds the view: many frames later the head and the camera have not moved.
TEST(ViewerPath, PauseHoldsTheView) {
    using namespace pathtest;
    const std::vector<Camera> views = writePath(pathFile("pause"), 12);
    ASSERT_EQ(views.size(), 12u);
    ViewRun r = runScript("path_pause",
                          "wait\npath play\nframes 4\npath pause\nwait\nstats p1.json\n"
                          "frames 30\nwait\nstats p2.json\nkey space\nframes 1\nstats p3.json\n",
                          false, playing(views, false));
    ASSERT_EQ(r.code, 0);
    nlohmann::json p1 = r.stats("p1.json"), p2 = r.stats("p2.json"), p3 = r.stats("p3.json");
    const uint32_t k = p1["path"]["frame"].get<uint32_t>();
    EXPECT_GE(k, 1u) << "played on from view 0";
    EXPECT_LT(k, 11u) << "paused before the end";
    EXPECT_EQ(p2["path"]["frame"], k);
    EXPECT_FALSE(p2["path"]["playing"].get<bool>());
    expectCamera(p2["camera"], views[k], "paused");
    expectCamera(p2["pipeline_a"]["camera"], views[k], "paused, A's image");
    EXPECT_TRUE(p3["path"]["playing"].get<bool>()) << "Space plays again";
}

// The reference's error of a view stays after the path moves on, marked stale and naming its
// view, until the reference of the new view is done.
TEST(ViewerPath, TheReferenceErrorStaysMarkedStaleWhileTheViewMoves) {
    using namespace pathtest;
    const std::vector<Camera> views = writePath(pathFile("stale"), 3);
    ASSERT_EQ(views.size(), 3u);
    ViewRun r = runScript("path_stale",
                          "wait\nstats fresh.json\npath seek 2\nframes 1\nstats moved.json\n"
                          "wait\nstats again.json\n",
                          /*reference=*/true, playing(views, false));
    ASSERT_EQ(r.code, 0);
    nlohmann::json fresh = r.stats("fresh.json"), moved = r.stats("moved.json"),
                   again = r.stats("again.json");
    ASSERT_FALSE(fresh["a_vs_reference_kept"].is_null());
    EXPECT_FALSE(fresh["a_vs_reference_kept"]["stale"].get<bool>());
    EXPECT_EQ(fresh["a_vs_reference_kept"]["view"], "path view 0 of 3");
    EXPECT_EQ(fresh["a_vs_reference_kept"]["rmse"], fresh["a_vs_reference"]["rmse"]);
    EXPECT_FALSE(moved.contains("a_vs_reference")) << "no metric against another view's reference";
    ASSERT_FALSE(moved["a_vs_reference_kept"].is_null())
        << "the error vanished when the view moved";
    EXPECT_TRUE(moved["a_vs_reference_kept"]["stale"].get<bool>());
    EXPECT_EQ(moved["a_vs_reference_kept"]["view"], "path view 0 of 3");
    EXPECT_EQ(moved["a_vs_reference_kept"]["rmse"], fresh["a_vs_reference"]["rmse"]);
    EXPECT_FALSE(again["a_vs_reference_kept"]["stale"].get<bool>());
    EXPECT_EQ(again["a_vs_reference_kept"]["view"], "path view 2 of 3");
}

// --light-motion alone: the camera stays, the lights move per view (the image changes) and the
// kept renderers follow them without a new plan.
TEST(ViewerPath, MovingLightsChangeTheImageAtAStillCamera) {
    using namespace pathtest;
    auto lightsOnly = [](LoopSetup& setup) {
        setup.viewer.initial.lightMotion = "orbit:0.5";
        setup.viewer.path.frames = 3;
        setup.viewer.path.source = "--light-motion";
    };
    ViewRun r = runScript("light_motion",
                          "exposure 0\nsplit 1\nwait\nstats l0.json\nscreenshot l0.png\n"
                          "path seek 2\nwait\nstats l2.json\nscreenshot l2.png\n",
                          false, lightsOnly);
    ASSERT_EQ(r.code, 0);
    nlohmann::json l0 = r.stats("l0.json"), l2 = r.stats("l2.json");
    EXPECT_EQ(l2["path"]["light_frame"], 2);
    EXPECT_EQ(l0["camera"], l2["camera"]);
    EXPECT_FALSE(l2["pipeline_a"]["planned"].get<bool>()) << "moved lights planned again";
    EXPECT_GT(sceneAreaDiffers(r.shot("l0.png"), r.shot("l2.png")), 0u);
}

// A script's path lines need a path, a seek beyond it and a file that does not read are refused
// with the line; `path load` of a good file plays as --camera-path does.
TEST(ViewerPath, PathLinesWithoutAPathOrOutOfRangeFail) {
    using namespace pathtest;
    EXPECT_EQ(runScript("path_none", "path play\n").code, 2);
    const std::vector<Camera> views = writePath(pathFile("range"), 3);
    EXPECT_EQ(runScript("path_range", "path seek 3\n", false, playing(views, false)).code, 2);
    EXPECT_EQ(runScript("path_load_bad", "path load missing.json\n").code, 2);
    // A good file loads at its view 0, paused, and plays.
    ViewRun loaded = runScript("path_load", "path load " + pathFile("range") +
                                                "\nstats loaded.json\npath seek 2\nwait\nstats seek.json\n");
    ASSERT_EQ(loaded.code, 0);
    EXPECT_EQ(loaded.stats("loaded.json")["path"]["frames"], 3);
    EXPECT_FALSE(loaded.stats("loaded.json")["path"]["playing"].get<bool>());
    expectCamera(loaded.stats("seek.json")["pipeline_a"]["camera"], views[2], "loaded, view 2");
}

// A bad path file or light motion: one line naming the problem, exit 2, before any window.
TEST(ViewerPath, ABadPathFileIsOneLineAndExitTwo) {
    const std::string dir =
        (std::filesystem::temp_directory_path() / "triptych_view_badpath").string();
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::ofstream(dir + "/script.txt") << "wait\n";
    std::ofstream(dir + "/bad.json")
        << R"({"schema": "triptych.camera_path/1", "frames": 0, "keys": []})";
    auto run = [&](const std::string& args) {
        const std::string err = dir + "/stderr.txt";
        const std::string cmd = std::string(TP_TRIPTYCH_EXE) +
                                " view builtin:courtyard-small --res 160x90 --headless --script " +
                                dir + "/script.txt --out " + dir + "/out " + args + " 2>" + err +
                                " >/dev/null";
        const int status = std::system(cmd.c_str());
        std::ifstream in(err);
        std::vector<std::string> lines;
        for (std::string l; std::getline(in, l);)
            lines.push_back(l);
        return std::pair{WIFEXITED(status) ? WEXITSTATUS(status) : -1, lines};
    };
    for (const std::string& args :
         {"--camera-path " + dir + "/bad.json", "--camera-path " + dir + "/missing.json",
          std::string("--light-motion spin")}) {
        auto [code, lines] = run(args);
        EXPECT_EQ(code, 2) << args;
        ASSERT_EQ(lines.size(), 1u) << args;
        EXPECT_EQ(lines[0].rfind("triptych: ", 0), 0u) << lines[0];
        const std::string named = args.substr(args.find(' ') + 1);
        EXPECT_NE(lines[0].find(named.find('/') != std::string::npos ? named : "spin"),
                  std::string::npos)
            << lines[0];
    }
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace tp::view
