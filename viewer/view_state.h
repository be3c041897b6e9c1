#pragma once
// Everything a user of the viewer can change, in one value, and the keys that say what a
// change must rebuild (docs/viewer.md, "What rebuilds what"):
//   sceneKey   scene file or builtin name        -> reload the scene and upload it again
//   lightsKey  light count/seed/types/range/...  -> regenerate lights, upload only them
//   planKey    + resolution, MSAA, knobs         -> plan the renderer again and render
//   renderKey  + camera, moved lights' frame     -> the kept renderer follows the view, renders
//   everything else (split, flip, difference, exposure, overlay) is display only: no render.
#include <cstdint>
#include <map>
#include <string>

#include "core/cli/options.h"
#include "core/scene/scene.h"

namespace tp::view {

enum class DisplayMode { Split, Difference, Overlay };

struct ViewState {
    cli::SceneOptions scene;
    uint32_t width = 320, height = 180, msaa = 1;
    std::map<std::string, std::string> knobs; // every registered knob, defaults filled in
    std::string pipelineA, pipelineB;         // B may be the reference
    Camera camera;
    bool cameraFromScene = true; // not yet moved: take the scene's camera when it loads
    bool autoExposure = true;
    float exposureEv = 0.0f;
    DisplayMode mode = DisplayMode::Split;
    float split = 0.5f;    // divider position, share of the width from the left
    bool flip = false;     // A and B swapped (the flip key)
    std::string overlay;   // debug image name shown in Overlay mode
    bool reference = true; // keep a reference of the current view rendering in the background
    // --light-motion as lightMotionToString writes it ("none", "orbit:0.05", ...; seeded by the
    // light seed) and the frame whose lights are shown: moved lights keep their count, so the
    // kept renderers follow them as they follow a camera move (no new plan).
    std::string lightMotion = "none";
    uint32_t lightFrame = 0;
};

std::string sceneKey(const ViewState& s);
std::string lightsKey(const ViewState& s);
// The moved lights' part of the view ("" when the lights do not move: the frame is then moot).
std::string motionKey(const ViewState& s);
// What a pipeline's image depends on (pipeline name excluded; debug: overlays requested).
std::string renderKey(const ViewState& s, bool debug);
// What a planned renderer depends on: renderKey without the camera (a camera move is followed
// by the kept renderer, render_worker.h).
std::string planKey(const ViewState& s, bool debug);
// What the reference depends on: a reference whose key differs from the current one is stale.
std::string referenceKey(const ViewState& s);
std::string cameraText(const Camera& c);

// The viewer's image: each side 8 to 8192 (the panel clamps to these, and to the device's limit).
inline constexpr uint32_t kViewMinSide = 8, kViewMaxSide = 8192;
// WIDTHxHEIGHT within those sides (view --res, the script's res); false otherwise.
bool parseViewResolution(const std::string& text, uint32_t& width, uint32_t& height);

} // namespace tp::view
