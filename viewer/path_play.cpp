// Playing a camera path and moving lights (path_player.h): the play head sets the state's
// camera and light frame; the workers render that view like any other, and the kept renderers
// follow it (render_worker.h).
#include <cstdio>

#include "core/camera/camera_path.h"
#include "core/reference/reference_renderer.h"
#include "viewer/viewer_app.h"

namespace tp::view {

void ViewerApp::showPathView() {
    if (!player_.views.empty()) {
        state_.camera = player_.views[player_.frame];
        state_.cameraFromScene = false;
    }
    state_.lightFrame = player_.frame;
}

void ViewerApp::setPlaying(bool playing) {
    player_.playing = playing && player_.loaded();
    // Play at the end starts the path again (it stopped there).
    if (player_.playing && player_.frame + 1 >= player_.frames) seekPath(0);
}

void ViewerApp::seekPath(uint32_t view) {
    if (!player_.loaded()) return;
    player_.seek(view);
    showPathView();
}

void ViewerApp::loadPath(const std::string& file) {
    Result<std::vector<Camera>> views = readCameraPath(file, options_.pathFrames);
    if (!views) {
        error_ = views.error();
        return;
    }
    player_.views = std::move(*views);
    player_.frames = uint32_t(player_.views.size());
    player_.source = file;
    player_.frame = 0;
    player_.playing = false;
    showPathView();
    error_.clear();
}

void ViewerApp::pauseForUserMove() {
    if (!player_.views.empty()) player_.playing = false; // the path would take the camera back
}

// The pipelines shown have their images of the current view. The reference is not waited for
// (seconds on lavapipe): it renders the latest view it can, and its error is marked stale
// meanwhile; it sets the pace only when both sides show it.
bool ViewerApp::pathViewShown() const {
    const std::string key = renderKey(state_, state_.mode == DisplayMode::Overlay);
    bool any = false;
    for (const std::string& p : {state_.pipelineA, state_.pipelineB}) {
        if (p == kReferenceRenderer) continue;
        const Shown* s = shownFor(p);
        if (!s || s->key != key) return false;
        any = true;
    }
    return any || (reference_ && reference_->key == referenceKey(state_));
}

void ViewerApp::advancePath() {
    if (!player_.playing || !pathViewShown()) return;
    for (const Shown* s : {shownA(), shownB()})
        if (s && !s->error.empty()) { // a view that failed to render stops the head on it
            player_.playing = false;
            return;
        }
    if (player_.advance()) showPathView();
}

std::string ViewerApp::viewLabel() const {
    std::string label;
    if (!player_.views.empty() &&
        cameraText(state_.camera) == cameraText(player_.views[player_.frame])) {
        label =
            "path view " + std::to_string(player_.frame) + " of " + std::to_string(player_.frames);
    } else {
        const Camera& c = state_.camera;
        char text[160];
        std::snprintf(text, sizeof text, "camera at %.3g %.3g %.3g to %.3g %.3g %.3g", c.position.x,
                      c.position.y, c.position.z, c.target.x, c.target.y, c.target.z);
        label = text;
    }
    if (state_.lightMotion != "none")
        label += ", lights of frame " + std::to_string(state_.lightFrame);
    return label;
}

} // namespace tp::view
