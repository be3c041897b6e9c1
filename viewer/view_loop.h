#pragma once
// The two ways the viewer runs: offscreen (headless.cpp) and in a window (window_loop.cpp).
// Both create the UI's own device, the ImGui context and a ViewerApp, and drive the same
// frame: script or input, app.frame(), the scene area and the panels drawn by UiRenderer.
#include <optional>
#include <string>
#include <vector>

#include "viewer/script.h"
#include "viewer/viewer_app.h"

namespace tp::view {

struct LoopSetup {
    ViewerOptions viewer;
    std::optional<std::vector<ScriptLine>> script;
    std::string scriptPath;
    std::string out = "view_out";
    double waitLimitSeconds = 600;
    int quitAfterFrames = 0; // window: close after this many frames (0: when the user does)
};

// Exit codes as the CLI's: 0, 2 (a script line failed / no display), 3 (validation messages).
int runHeadless(const LoopSetup& setup);
int runWindow(const LoopSetup& setup);

// Shared by both: the ImGui context (no imgui.ini written), and the end of a run.
void createImGuiContext();
int finish(ViewerApp& app, const GpuContext& ui, const std::string& scriptError);
// The UI surface for the scene area at its size: the area plus the panel, at least 600 high.
void surfaceSize(const ViewerApp& app, uint32_t& width, uint32_t& height);

} // namespace tp::view
