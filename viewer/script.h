#pragma once
// The viewer's script: one action per line, the same actions a user takes with the mouse and
// keys (docs/viewer.md lists them). `triptych view --headless --script FILE` runs it offscreen
// and its screenshots hold the UI; the window runs it too (without screenshots).
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/image/image.h"
#include "core/util/result.h"

namespace tp::view {

class ViewerApp;

// A script that cannot go on (a bad line, a wait past its limit): one line for the user.
struct ScriptError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct ScriptLine {
    int number = 0;
    std::vector<std::string> words;
};

// Every script error, read or run, in one form: "PATH:LINE: message" ("PATH: message" for
// line 0, the file as a whole), made printable: messages quote the file's words, whose
// control characters and bytes that are not UTF-8 would reach the terminal.
std::string scriptErrorLine(const std::string& path, int line, const std::string& message);

// Reads and checks every line (command names and argument counts) before anything runs.
Result<std::vector<ScriptLine>> readScript(const std::string& path);

// The mouse as the script drives it (the window takes GLFW's instead).
struct ScriptMouse {
    float x = -1.0f, y = -1.0f;
    bool down = false;
};

class ScriptRunner {
  public:
    ScriptRunner(std::vector<ScriptLine> lines, std::string path, std::string outDir,
                 double waitLimitSeconds, bool screenshots);
    // Before each UI frame: applies lines until one needs frames to pass.
    void beforeFrame(ViewerApp& app, ScriptMouse& mouse);
    // The frame after beforeFrame must be read back (a screenshot is due).
    bool wantsScreenshot() const { return screenshotDue_; }
    void afterFrame(ViewerApp& app, const ImageRGBA* frame, double frameMs);
    bool done() const { return next_ >= lines_.size() && !blocked(); }

  private:
    enum class Wait { None, Frames, Settled, Screenshot, Export, Drag, Bench };
    bool blocked() const { return wait_ != Wait::None; }
    // One line, by what it touches: the view's settings, the camera, the display and the
    // mouse, or the waits and outputs.
    void apply(ViewerApp& app, ScriptMouse& mouse, const ScriptLine& line);
    void applyViewSetting(ViewerApp& app, const ScriptLine& line);
    void applyLights(ViewerApp& app, const ScriptLine& line);
    void applyCamera(ViewerApp& app, const ScriptLine& line);
    void applyPath(ViewerApp& app, const ScriptLine& line);
    void applyDisplay(ViewerApp& app, ScriptMouse& mouse, const ScriptLine& line);
    void applyWaitOrOutput(ViewerApp& app, const ScriptLine& line);
    // Word i of the line as a finite number, or an integer in [lo, hi]; fail() otherwise.
    float numberAt(const ScriptLine& line, size_t i) const;
    uint64_t integerAt(const ScriptLine& line, size_t i, uint64_t lo, uint64_t hi) const;
    bool stillWaiting(ViewerApp& app, ScriptMouse& mouse);
    [[noreturn]] void fail(const ScriptLine& line, const std::string& message) const;
    void writeStats(ViewerApp& app, const std::string& file) const;
    std::string inOut(const std::string& file) const;
    bool benchStep(ViewerApp& app); // true while renders remain

    std::vector<ScriptLine> lines_;
    std::string path_, out_;
    double waitLimit_;
    bool screenshots_;
    size_t next_ = 0;
    size_t startedLine_ = SIZE_MAX;
    const ScriptLine* current_ = nullptr;
    Wait wait_ = Wait::None;
    int framesLeft_ = 0;
    std::chrono::steady_clock::time_point waitStart_;
    bool screenshotDue_ = false;
    std::string screenshotFile_;
    float dragTo_[2] = {};
    int dragStage_ = 0;
    // bench: renders left, their times, the UI frame times while they ran.
    int benchLeft_ = 0, benchTotal_ = 0;
    bool benchRecordDue_ = false;
    std::string benchFile_;
    std::vector<double> benchRenderMs_, benchGpuMs_, benchUiMs_, benchUpdateMs_, benchLatencyMs_,
        benchFramesMs_;
    std::map<std::string, std::vector<double>> benchSteps_;
    uint32_t benchPlanned_ = 0; // renders that planned the renderer (not a followed camera move)
};

} // namespace tp::view
