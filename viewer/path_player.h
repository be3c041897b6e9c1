#pragma once
// The play head of a camera path (--camera-path) and of moving lights (--light-motion) in the
// viewer (docs/viewer.md, "Playing a path"). The views are read by core/camera/camera_path.h
// and each view's lights come from core/scene/light_motion.h in the render workers, the same
// code `compare --camera-path` runs; this holds only which view is shown and whether it moves.
//
// Playback is locked to the renders: the head moves one view each time the pipelines' image of
// the current view has been shown, so every view of the path is rendered and shown once, at the
// pipelines' own rate. A clock-driven head would skip most of a path on lavapipe (a render
// there takes tens to hundreds of milliseconds) and show a different subset each run.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace tp::view {

struct PathPlayer {
    std::vector<Camera> views; // the path's views; empty: the camera stays the user's
    uint32_t frames = 0;       // views on the time line (lights alone: --path-frames); 0: none
    std::string source;        // the file, for the panel
    uint32_t frame = 0;        // the view shown (or being rendered)
    bool playing = false;
    bool loop = false; // at the end: back to view 0 instead of stopping

    bool loaded() const { return frames > 0; }
    // The next view; at the last one it stops (or loops). False when it stopped.
    bool advance();
    void seek(uint32_t view) { frame = frames ? std::min(view, frames - 1) : 0; }
};

} // namespace tp::view
