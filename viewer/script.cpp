#include "viewer/script.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/cli/scene_input.h"
#include "core/image/image_io.h"
#include "core/renderer/renderer.h"
#include "core/renderer/view_settings.h"
#include "core/util/clock.h"
#include "core/util/files.h"
#include "viewer/keys.h"
#include "viewer/viewer_app.h"

namespace tp::view {
namespace {

struct CommandSpec {
    size_t minArgs, maxArgs;
    const char* usage;
};

// Every command, its argument count and its usage line (docs/viewer.md has the same list).
const std::map<std::string, CommandSpec>& commands() {
    static const std::map<std::string, CommandSpec> table = {
        {"pipeline", {2, 2, "pipeline a|b NAME"}},
        {"knob", {2, 2, "knob NAME VALUE"}},
        {"lights", {2, 2, "lights count|seed|types|range|intensity VALUE"}},
        {"msaa", {1, 1, "msaa N"}},
        {"res", {1, 1, "res WIDTHxHEIGHT"}},
        {"exposure", {1, 1, "exposure auto|EV"}},
        {"camera",
         {1, 3,
          "camera move F R U | orbit YAW PITCH | turn YAW PITCH | reset | load FILE | save FILE | "
          "key | path FILE"}},
        {"path", {1, 2, "path play | pause | seek VIEW | loop on|off | load FILE"}},
        {"split", {1, 1, "split SHARE (0 to 1)"}},
        {"flip", {0, 1, "flip [on|off]"}},
        {"mode", {1, 2, "mode split|difference|overlay [DEBUG_IMAGE]"}},
        {"hover", {2, 2, "hover X Y"}},
        {"drag", {4, 4, "drag X0 Y0 X1 Y1"}},
        {"key", {1, 1, "key LETTER|space"}},
        {"reference", {1, 1, "reference on|off|now"}},
        {"scene", {1, 1, "scene FILE|builtin:NAME"}},
        {"wait", {0, 0, "wait"}},
        {"frames", {1, 1, "frames N"}},
        {"screenshot", {1, 1, "screenshot FILE.png"}},
        {"stats", {1, 1, "stats FILE.json"}},
        {"export", {1, 1, "export DIR"}},
        {"bench", {2, 2, "bench RENDERS FILE.json"}},
        {"expect-error", {1, 1, "expect-error TEXT"}},
    };
    return table;
}

float number(const std::string& text, bool& ok) {
    char* end = nullptr;
    float v = std::strtof(text.c_str(), &end);
    ok = end && *end == '\0' && !text.empty() && std::isfinite(v);
    return v;
}

} // namespace

std::string scriptErrorLine(const std::string& path, int line, const std::string& message) {
    const std::string where = line > 0 ? path + ":" + std::to_string(line) : path;
    return printableLine(where + ": " + message);
}

Result<std::vector<ScriptLine>> readScript(const std::string& path) {
    auto refuse = [&](int line, const std::string& message) {
        return Error{scriptErrorLine(path, line, message)};
    };
    // A directory opens as a stream and reads as no lines: it would run as an empty script.
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return refuse(0, "is a directory, not a script");
    std::ifstream in(path);
    if (!in) return refuse(0, "cannot open the file");
    std::vector<ScriptLine> lines;
    std::string text;
    int n = 1;
    for (; std::getline(in, text); ++n) {
        if (size_t hash = text.find('#'); hash != std::string::npos) text.resize(hash);
        std::istringstream words(text);
        ScriptLine line{n, {}};
        for (std::string w; words >> w;)
            line.words.push_back(w);
        if (line.words.empty()) continue;
        auto it = commands().find(line.words[0]);
        if (it == commands().end()) return refuse(n, "unknown command '" + line.words[0] + "'");
        size_t args = line.words.size() - 1;
        if (args < it->second.minArgs || args > it->second.maxArgs)
            return refuse(n, "expected '" + std::string(it->second.usage) + "'");
        lines.push_back(std::move(line));
    }
    if (in.bad()) return refuse(n, "cannot read the file past here");
    return lines;
}

ScriptRunner::ScriptRunner(std::vector<ScriptLine> lines, std::string path, std::string outDir,
                           double waitLimitSeconds, bool screenshots)
    : lines_(std::move(lines)), path_(std::move(path)), out_(std::move(outDir)),
      waitLimit_(waitLimitSeconds), screenshots_(screenshots) {}

void ScriptRunner::fail(const ScriptLine& line, const std::string& message) const {
    throw ScriptError(scriptErrorLine(path_, line.number, message));
}

void ScriptRunner::beforeFrame(ViewerApp& app, ScriptMouse& mouse) {
    while (true) {
        if (blocked() && stillWaiting(app, mouse)) return;
        if (next_ >= lines_.size()) return;
        if (next_ != startedLine_)
            waitStart_ = std::chrono::steady_clock::now(); // not when a line runs again
        startedLine_ = next_;
        current_ = &lines_[next_++];
        apply(app, mouse, *current_);
        if (blocked()) return; // a line that waits sees at least one frame first
    }
}

// False when the current wait is over (the next line may run).
bool ScriptRunner::stillWaiting(ViewerApp& app, ScriptMouse& mouse) {
    double waited = secondsSince(waitStart_);
    if (waited > waitLimit_)
        fail(*current_,
             "still waiting after " + std::to_string(int(waitLimit_)) + " s (--wait-limit)");
    switch (wait_) {
    case Wait::Frames:
    case Wait::Screenshot:
        if (framesLeft_ > 0) return true;
        break;
    case Wait::Settled:
        // Two frames after settling: the panels show what the new images say.
        if (!app.settled()) {
            framesLeft_ = 2;
            return true;
        }
        if (framesLeft_ > 0) return true;
        break;
    case Wait::Export:
        if (app.exporting()) return true;
        if (app.exportStatus().find("failed") != std::string::npos)
            fail(*current_, app.exportStatus());
        break;
    case Wait::Drag:
        if (dragStage_ == 1) { // pressed last frame: move
            mouse.x = dragTo_[0], mouse.y = dragTo_[1];
            dragStage_ = 2;
            return true;
        }
        if (dragStage_ == 2) { // moved: release
            mouse.down = false;
            dragStage_ = 3;
            return true;
        }
        break;
    case Wait::Bench:
        if (!app.settled()) return true;
        if (benchStep(app)) return true;
        break;
    case Wait::None:
        break;
    }
    wait_ = Wait::None;
    return false;
}

void ScriptRunner::afterFrame(ViewerApp&, const ImageRGBA* frame, double frameMs) {
    if (wait_ == Wait::Bench) benchUiMs_.push_back(frameMs);
    if (framesLeft_ > 0) --framesLeft_;
    if (screenshotDue_ && frame) {
        screenshotDue_ = false;
        if (Status s = writePng(screenshotFile_, *frame); !s) fail(*current_, s.error());
    }
    // The screenshot is of the frame after the layout settled (ImGui sizes windows in a frame).
    if (wait_ == Wait::Screenshot && framesLeft_ == 1 && screenshots_) screenshotDue_ = true;
}

// Files a script names are in --out unless given as absolute paths.
std::string ScriptRunner::inOut(const std::string& file) const {
    return !file.empty() && file[0] == '/' ? file : out_ + "/" + file;
}

float ScriptRunner::numberAt(const ScriptLine& line, size_t i) const {
    bool ok = true;
    const float v = number(line.words[i], ok);
    if (!ok) fail(line, "'" + line.words[i] + "' is not a number");
    return v;
}

// Counts and seeds are read as integers: through float a seed above 2^24 would change.
uint64_t ScriptRunner::integerAt(const ScriptLine& line, size_t i, uint64_t lo, uint64_t hi) const {
    const std::string& word = line.words[i];
    uint64_t v = 0;
    auto [end, err] = std::from_chars(word.data(), word.data() + word.size(), v);
    if (err != std::errc() || end != word.data() + word.size() || v < lo || v > hi)
        fail(line, "'" + word + "' is not an integer from " + std::to_string(lo) + " to " +
                       std::to_string(hi));
    return v;
}

void ScriptRunner::apply(ViewerApp& app, ScriptMouse& mouse, const ScriptLine& line) {
    const std::string& cmd = line.words[0];
    if (cmd == "pipeline" || cmd == "knob" || cmd == "lights" || cmd == "msaa" || cmd == "res" ||
        cmd == "exposure")
        applyViewSetting(app, line);
    else if (cmd == "camera")
        applyCamera(app, line);
    else if (cmd == "path")
        applyPath(app, line);
    else if (cmd == "wait" || cmd == "frames" || cmd == "screenshot" || cmd == "stats" ||
             cmd == "export" || cmd == "bench" || cmd == "expect-error")
        applyWaitOrOutput(app, line);
    else
        applyDisplay(app, mouse, line);
}

// What the image depends on: a change here renders again. Each value is checked as the
// command line checks it (checkSetting, generatorOptions), with the same one-line errors.
void ScriptRunner::applyViewSetting(ViewerApp& app, const ScriptLine& line) {
    const std::vector<std::string>& w = line.words;
    const std::string& cmd = w[0];
    ViewState& s = app.state();
    if (cmd == "pipeline") {
        if (w[1] != "a" && w[1] != "b") fail(line, "expected 'pipeline a|b NAME'");
        if (Result<const RendererEntry*> e = findRenderer(w[2]); !e) fail(line, e.error());
        (w[1] == "a" ? s.pipelineA : s.pipelineB) = w[2];
    } else if (cmd == "knob") {
        if (Status c = checkSetting(w[1], w[2]); !c) fail(line, c.error());
        s.knobs[w[1]] = w[2];
    } else if (cmd == "lights") {
        applyLights(app, line);
    } else if (cmd == "msaa") {
        if (Status c = checkSetting(kMsaaSetting, w[1]); !c) fail(line, c.error());
        const uint32_t n = uint32_t(std::stoul(w[1]));
        // The panel greys such a count out; a script is refused with the same reason.
        if (!app.supportsMsaa(n))
            fail(line, "msaa " + w[1] + ": not supported by " + app.deviceName());
        s.msaa = n;
    } else if (cmd == "res") {
        if (!parseViewResolution(w[1], s.width, s.height))
            fail(line, "expected 'res WIDTHxHEIGHT', each side " + std::to_string(kViewMinSide) +
                           " to " + std::to_string(kViewMaxSide));
    } else if (cmd == "exposure") {
        s.autoExposure = w[1] == "auto";
        if (!s.autoExposure) s.exposureEv = numberAt(line, 1);
    }
}

void ScriptRunner::applyLights(ViewerApp& app, const ScriptLine& line) {
    const std::vector<std::string>& w = line.words;
    cli::SceneOptions o = app.state().scene;
    if (w[1] == "count")
        o.lightCount = int(integerAt(line, 2, 0, 1u << 30));
    else if (w[1] == "seed")
        o.seed = integerAt(line, 2, 0, UINT64_MAX);
    else if (w[1] == "types")
        o.lightTypes = w[2];
    else if (w[1] == "range")
        o.lightRadius = w[2];
    else if (w[1] == "intensity")
        o.lightIntensity = w[2];
    else
        fail(line, "expected 'lights count|seed|types|range|intensity VALUE'");
    try {
        (void)cli::generatorOptions(o);
    } catch (const std::exception& e) {
        fail(line, e.what());
    }
    app.state().scene = o;
}

void ScriptRunner::applyCamera(ViewerApp& app, const ScriptLine& line) {
    const std::vector<std::string>& w = line.words;
    if (!app.sceneLoaded()) { // a move needs the scene's camera: run this line again next frame
        if (!app.lastError().empty() && app.settled())
            fail(line, "no scene to move in: " + app.lastError());
        double waited = secondsSince(waitStart_);
        if (waited > waitLimit_)
            fail(line, "the scene did not load in " + std::to_string(int(waitLimit_)) + " s");
        --next_;
        wait_ = Wait::Frames, framesLeft_ = 1;
        return;
    }
    auto num = [&](size_t i) { return numberAt(line, i); };
    if (w[1] == "reset")
        app.resetCamera();
    else if (w[1] == "move" && w.size() == 5)
        app.moveCamera(num(2), num(3), num(4));
    else if (w[1] == "orbit" && w.size() == 4)
        app.orbitCamera(num(2), num(3));
    else if (w[1] == "turn" && w.size() == 4)
        app.turnCamera(num(2), num(3));
    else if (w[1] == "load" && w.size() == 3)
        app.loadBookmark(inOut(w[2]));
    else if (w[1] == "save" && w.size() == 3)
        app.saveBookmark(inOut(w[2]));
    else if (w[1] == "key" && w.size() == 2)
        app.addPathKey();
    else if (w[1] == "path" && w.size() == 3)
        app.savePath(inOut(w[2]));
    else
        fail(line, std::string("expected '") + commands().at("camera").usage + "'");
    if (!app.lastError().empty()) fail(line, app.lastError());
}

// The play head of --camera-path / --light-motion (path_player.h).
void ScriptRunner::applyPath(ViewerApp& app, const ScriptLine& line) {
    const std::vector<std::string>& w = line.words;
    const bool one = w.size() == 2, two = w.size() == 3;
    if (two && w[1] == "load") {
        app.loadPath(inOut(w[2]));
        if (!app.lastError().empty()) fail(line, app.lastError());
        return;
    }
    if (!app.path().loaded())
        fail(line, "no path: give --camera-path FILE or --light-motion MODE, or 'path load FILE'");
    if (one && (w[1] == "play" || w[1] == "pause"))
        app.setPlaying(w[1] == "play");
    else if (two && w[1] == "seek")
        app.seekPath(uint32_t(integerAt(line, 2, 0, app.path().frames - 1)));
    else if (two && w[1] == "loop" && (w[2] == "on" || w[2] == "off"))
        app.setPathLoop(w[2] == "on");
    else
        fail(line, std::string("expected '") + commands().at("path").usage + "'");
}

// Display only (no render) and the user's hands: split, flip, mode, mouse, keys, the
// reference switch, the scene.
void ScriptRunner::applyDisplay(ViewerApp& app, ScriptMouse& mouse, const ScriptLine& line) {
    const std::vector<std::string>& w = line.words;
    const std::string& cmd = w[0];
    ViewState& s = app.state();
    auto num = [&](size_t i) { return numberAt(line, i); };
    if (cmd == "split") {
        float v = num(1);
        if (v < 0.0f || v > 1.0f) fail(line, "split must be between 0 and 1");
        app.setSplit(v);
    } else if (cmd == "flip") {
        bool want = w.size() == 1 ? !s.flip : w[1] == "on";
        if (want != s.flip) app.toggleFlip();
    } else if (cmd == "mode") {
        if (w[1] == "split")
            s.mode = DisplayMode::Split;
        else if (w[1] == "difference")
            s.mode = DisplayMode::Difference;
        else if (w[1] == "overlay")
            s.mode = DisplayMode::Overlay;
        else
            fail(line, "expected 'mode split|difference|overlay [DEBUG_IMAGE]'");
        if (w.size() == 3) s.overlay = w[2];
    } else if (cmd == "hover") {
        mouse.x = num(1), mouse.y = num(2);
        wait_ = Wait::Frames, framesLeft_ = 1;
    } else if (cmd == "drag") {
        mouse.x = num(1), mouse.y = num(2), mouse.down = true;
        dragTo_[0] = num(3), dragTo_[1] = num(4);
        wait_ = Wait::Drag, dragStage_ = 1;
    } else if (cmd == "key") {
        // Space is spelled out: a script's words are split on spaces.
        const int key = w[1] == "space" ? ' ' : std::toupper(static_cast<unsigned char>(w[1][0]));
        if ((w[1].size() != 1 && w[1] != "space") || !applyKey(app, key))
            fail(line, "no such key '" + w[1] + "' (docs/viewer.md lists the keys)");
    } else if (cmd == "reference") {
        if (w[1] == "now")
            app.requestReference();
        else
            s.reference = w[1] == "on";
    } else if (cmd == "scene") {
        s.scene.scene = w[1];
        s.cameraFromScene = true;
    }
}

// Lines that wait for frames or write files.
void ScriptRunner::applyWaitOrOutput(ViewerApp& app, const ScriptLine& line) {
    const std::vector<std::string>& w = line.words;
    const std::string& cmd = w[0];
    if (cmd == "wait") {
        wait_ = Wait::Settled, framesLeft_ = 2;
    } else if (cmd == "frames") {
        wait_ = Wait::Frames, framesLeft_ = int(integerAt(line, 1, 1, 100000));
    } else if (cmd == "screenshot") {
        screenshotFile_ = inOut(w[1]);
        wait_ = Wait::Screenshot, framesLeft_ = screenshots_ ? 3 : 1;
    } else if (cmd == "stats") {
        writeStats(app, inOut(w[1]));
    } else if (cmd == "export") {
        app.startExport(inOut(w[1]));
        if (!app.lastError().empty()) fail(line, app.lastError());
        wait_ = Wait::Export;
    } else if (cmd == "bench") {
        benchTotal_ = benchLeft_ = int(integerAt(line, 1, 1, 100000));
        benchFile_ = inOut(w[2]);
        benchRenderMs_.clear(), benchGpuMs_.clear(), benchUiMs_.clear(), benchUpdateMs_.clear();
        benchLatencyMs_.clear(), benchFramesMs_.clear();
        benchSteps_.clear();
        benchPlanned_ = 0;
        benchRecordDue_ = false;
        wait_ = Wait::Bench;
    } else if (cmd == "expect-error") {
        if (app.lastError().find(w[1]) == std::string::npos)
            fail(line, "expected an error containing '" + w[1] + "', the viewer shows '" +
                           app.lastError() + "'");
    }
}

} // namespace tp::view
