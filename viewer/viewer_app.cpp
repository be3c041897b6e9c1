#include "viewer/viewer_app.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "core/image/tonemap.h"
#include "core/util/clock.h"
#include "core/reference/reference_renderer.h"
#include "viewer/camera_control.h"
#include "viewer/pixel_lights.h"

namespace tp::view {
namespace {

// How close (pixels) to the divider a press grabs it instead of orbiting the camera.
constexpr float kGrabDistance = 4.0f;

// Which image a composite or a metric was made from (an address could be reused).
std::string serialKey(const Shown* s) {
    return s && s->run ? std::to_string(s->serial) + "|" : "-|";
}

} // namespace

void TimingHistory::add(const std::vector<TimingStats>& timings, double renderWallMs) {
    wallMs.push_back(renderWallMs);
    while (wallMs.size() > kHistory)
        wallMs.pop_front();
    for (const TimingStats& t : timings) {
        if (!passes.count(t.name)) order.push_back(t.name);
        std::deque<double>& h = passes[t.name];
        h.push_back(t.medianMs);
        while (h.size() > kHistory)
            h.pop_front();
    }
}

ViewerApp::ViewerApp(GpuContext& uiContext, ViewerOptions options)
    : ui_(uiContext), options_(std::move(options)), state_(options_.initial),
      draft_(options_.initial) {
    deviceName_ = ui_.info.name;
    sampleCounts_ = ui_.caps.colorSampleCounts;
    shared_ = options_.shareDevice == "on" || (options_.shareDevice == "auto" && ui_.queueCount > 1);
    gpuComposite_ = std::make_unique<GpuComposite>(ui_);
    // The reference keeps a device of its own: its image is wanted on the CPU (the error).
    worker_ = std::make_unique<RenderWorker>(options_.context, "pipelines", shared_ ? &ui_ : nullptr,
                                             true);
    referenceWorker_ = std::make_unique<RenderWorker>(options_.context, "reference");
    player_ = options_.path;
    if (player_.loaded()) showPathView();
}

ViewerApp::~ViewerApp() {
    stop();
}

std::vector<std::string> ViewerApp::stop() {
    std::vector<std::string> messages;
    // The display images are the worker's: let go of them (and of any UI frame reading one)
    // before its device context goes.
    ui_.waitIdle();
    shown_.clear();
    reference_.reset();
    composedFor_.clear();
    for (auto* w : {&worker_, &referenceWorker_}) {
        if (!*w) continue;
        std::vector<std::string> m = (*w)->stop();
        messages.insert(messages.end(), m.begin(), m.end());
        w->reset();
    }
    return messages;
}

void ViewerApp::setSplit(float share) {
    state_.split = std::clamp(share, 0.0f, 1.0f);
    sceneInputsChanged_ = true;
}

double frameGpuMs(const Shown* s) {
    return s && s->run ? frameMedianMs(*s->run) : 0.0;
}

const Shown* ViewerApp::shownFor(const std::string& pipeline) const {
    if (pipeline == kReferenceRenderer) return reference_ ? &*reference_ : nullptr;
    auto it = shown_.find(pipeline);
    return it == shown_.end() ? nullptr : &it->second;
}
const TimingHistory* ViewerApp::history(const std::string& pipeline) const {
    auto it = history_.find(pipeline);
    return it == history_.end() ? nullptr : &it->second;
}
const Shown* ViewerApp::shownA() const {
    return shownFor(state_.pipelineA);
}
const Shown* ViewerApp::shownB() const {
    return shownFor(state_.pipelineB);
}

bool ViewerApp::referenceStale() const {
    return !reference_ || reference_->key != referenceKey(state_);
}

bool ViewerApp::settled() const {
    // The next view is coming (unless a render failed: then the head waits on the error).
    if (player_.playing && error_.empty()) return false;
    if (!worker_->idle() || !referenceWorker_->idle()) return false;
    // A finished outcome not yet taken, or a state change not yet submitted.
    bool debug = state_.mode == DisplayMode::Overlay;
    if (submittedKey_ != renderKey(state_, debug)) return false;
    bool wantReference = state_.reference || state_.pipelineA == kReferenceRenderer ||
                         state_.pipelineB == kReferenceRenderer;
    if (wantReference && submittedReferenceKey_ != referenceKey(state_)) return false;
    // A scene that failed to load settles on its error (no image will come).
    return (shownA() != nullptr || !error_.empty()) && !sceneDirty_;
}

// What needs A's and B's pixels on the CPU: the error against the reference, the debug
// overlays, the inspector; and every image when the renderers have a device of their own.
bool ViewerApp::wantImages() const {
    return !shared_ || state_.reference || state_.mode == DisplayMode::Overlay || inspecting_;
}

void ViewerApp::submitJobs() {
    const bool debug = state_.mode == DisplayMode::Overlay;
    std::vector<std::string> pipelines;
    for (const std::string& p : {state_.pipelineA, state_.pipelineB})
        if (p != kReferenceRenderer &&
            std::find(pipelines.begin(), pipelines.end(), p) == pipelines.end())
            pipelines.push_back(p);
    const std::string key = renderKey(state_, debug);
    const bool images = wantImages();
    // The same view again when its pixels are now wanted on the CPU (the renderers follow no
    // view change: a frame and the readback).
    if (key != submittedKey_ || pipelines != submittedPipelines_ ||
        (images && !submittedImages_)) {
        RenderJob job{nextJob_++, state_, pipelines, debug, key, options_.timedFrames, options_.calibration,
                      options_.passStatistics, images};
        submittedImages_ = images;
        submittedAt_[job.id] = std::chrono::steady_clock::now();
        // Debug images of a pipeline only when an overlay is shown: they cost readbacks.
        worker_->submit(std::move(job));
        submittedKey_ = key;
        submittedPipelines_ = pipelines;
    }
    bool wantReference = state_.reference || referenceRequested_ ||
                         state_.pipelineA == kReferenceRenderer ||
                         state_.pipelineB == kReferenceRenderer;
    const std::string refKey = referenceKey(state_);
    if (wantReference && refKey != submittedReferenceKey_) {
        RenderJob job{nextJob_++, state_, {kReferenceRenderer}, false, refKey, 1, nullptr, options_.passStatistics};
        referenceWorker_->submit(std::move(job));
        submittedReferenceKey_ = refKey;
    }
    referenceRequested_ = false;
}

// A side of the GPU composite: the display copy where the renderer shares the UI's device,
// else its image on the CPU (uploaded once per serial).
namespace {
CompositeSide sideOf(const Shown* s) {
    if (!s || !s->run) return {};
    if (s->display) return {&s->display->image, nullptr, s->serial};
    if (s->hasImages()) return {nullptr, &s->run->hdr, s->serial};
    return {};
}
} // namespace

Composite ViewerApp::composeOnGpu(const CompositeInput& in, const Shown* a, const Shown* b,
                                  uint32_t w, uint32_t h) {
    Composite c = gpuComposite_->compose(in, sideOf(a), sideOf(b), w, h, targetBgra_);
    c.gpuBytes = gpuComposite_->bytes().buffer;
    return c;
}

void ViewerApp::recompose() {
    const Shown* a = shownA();
    const Shown* b = shownB();
    const RunResult* runA = a && a->run ? a->run.get() : nullptr;
    if (runA && a->serial != autoEvFor_) { // once per image, not per UI frame
        // From where the composite reads the image: a shared view keeps one exposure when its
        // pixels arrive on the CPU later (the GPU's float logs may differ in the last bits).
        autoEv_ = a->display || !a->hasImages() ? gpuComposite_->autoExposureEv(sideOf(a))
                                                : autoExposureEv(runA->hdr);
        autoEvFor_ = a->serial;
    }
    const float ev = state_.autoExposure ? autoEv_ : state_.exposureEv;
    const ImageRGBA* overlay = nullptr;
    if (runA)
        for (const DebugImage& d : runA->debugImages)
            if (d.name == state_.overlay && d.display) overlay = &d.image;
    char buf[160];
    std::snprintf(buf, sizeof(buf), "|%d|%.6f|%d|%.6f|%ux%u", int(state_.mode), state_.split,
                  int(state_.flip), ev, state_.width, state_.height);
    std::string key =
        serialKey(a) + serialKey(b) + (overlay ? state_.overlay : std::string("-")) + buf;
    if (key == composedFor_) return;
    const RunResult* runB = b && b->run ? b->run.get() : nullptr;
    CompositeInput in{runA && a->hasImages() ? &runA->hdr : nullptr,
                      runB && b->hasImages() ? &runB->hdr : nullptr,
                      overlay,
                      state_.mode,
                      state_.split,
                      state_.flip,
                      ev};
    // The images' own size: a render of the previous resolution stays shown until the new one
    // lands.
    const CompositeSide sideA = sideOf(a);
    uint32_t w = sideA.present() ? sideA.width() : state_.width;
    uint32_t h = sideA.present() ? sideA.height() : state_.height;
    // The debug overlays are images read back with the render: composed on the CPU.
    composite_ = state_.mode == DisplayMode::Overlay ? compose(in, w, h)
                                                     : composeOnGpu(in, a, b, w, h);
    composedFor_ = key;
    sceneDirty_ = true;
}

bool ViewerApp::takeSceneDirty() {
    bool d = sceneDirty_;
    sceneDirty_ = false;
    return d;
}

void ViewerApp::measureAgainstReference() {
    const Shown* a = shownA();
    const bool valid = a && a->hasImages() && !referenceStale() && reference_->run &&
                       a->key == submittedKey_;
    const float ev = state_.autoExposure ? autoEv_ : state_.exposureEv;
    // Measured once per pair of images (and exposure), not per UI frame.
    char evText[32];
    std::snprintf(evText, sizeof(evText), "|%.6f", ev);
    const std::string key = valid ? serialKey(a) + serialKey(&*reference_) + evText : "";
    if (key == measuredFor_) return;
    measuredFor_ = key;
    errorVsReference_.reset();
    errorVsReferenceDisplay_.reset();
    if (!valid) return; // no reference of this view, or A is of an older one
    const ImageRGBA& ref = reference_->run->hdr;
    if (ref.width != a->run->hdr.width || ref.height != a->run->hdr.height) return;
    MetricsOptions hdr;
    hdr.psnrPeak = brightestFiniteChannel(ref); // compare's HDR PSNR peak
    errorVsReference_ = computeError(a->run->hdr, ref, hdr);
    errorVsReferenceDisplay_ =
        computeError(tonemapToDisplay(a->run->hdr, ev), tonemapToDisplay(ref, ev));
    // The state is the reference's view here (its key is the current one).
    keptError_ = KeptError{*errorVsReference_, *errorVsReferenceDisplay_, viewLabel()};
}

void ViewerApp::handleSceneMouse() {
    ImGuiIO& io = ImGui::GetIO();
    const float w = float(composite_.width), h = float(composite_.height);
    const ImVec2 m = io.MousePos;
    const bool inside = m.x >= 0 && m.y >= 0 && m.x < w && m.y < h && !io.WantCaptureMouse;
    inspection_.valid = false;
    // Resting on the scene (no drag): the inspector wants the pixels, read back on request.
    inspecting_ = inside && m.y < float(state_.height) && !io.MouseDown[0] && !io.MouseDown[1];
    if (inside && m.y < float(state_.height)) {
        inspection_.valid = true;
        inspection_.x = uint32_t(m.x);
        inspection_.y = uint32_t(m.y);
        for (auto [shown, out] :
             {std::pair{shownA(), inspection_.a}, std::pair{shownB(), inspection_.b}}) {
            std::fill(out, out + 4, 0.0f);
            if (shown && shown->run && inspection_.x < shown->run->hdr.width &&
                inspection_.y < shown->run->hdr.height)
                std::copy_n(shown->run->hdr.at(inspection_.x, inspection_.y), 4, out);
        }
        inspectLights();
    }
    if (!io.MouseDown[0]) dragging_ = false;
    if (inside && io.MouseClicked[0] && state_.mode == DisplayMode::Split &&
        std::abs(m.x - float(dividerColumn(state_.split, composite_.width))) <= kGrabDistance)
        dragging_ = true;
    if (dragging_) {
        setSplit(m.x / w);
        return;
    }
    if (!inside) return;
    // Camera: left drag orbits, right drag turns the view (fly), the wheel dollies.
    const ImVec2 d = io.MouseDelta;
    if (io.MouseDown[0] && (d.x != 0 || d.y != 0))
        orbitCamera(d.x * 0.3f, d.y * 0.3f);
    else if (io.MouseDown[1] && (d.x != 0 || d.y != 0))
        turnCamera(d.x * 0.2f, d.y * 0.2f);
    if (io.MouseWheel != 0 && hasSceneCamera_) {
        pauseForUserMove();
        userCamera();
        dolly(state_.camera, io.MouseWheel * 0.1f);
    }
}

// The lights reaching the surface under the cursor, from A's depth, camera and lights; kept
// while the cursor stays on one pixel of one image.
void ViewerApp::inspectLights() {
    const Shown* a = shownA();
    std::string key =
        serialKey(a) + std::to_string(inspection_.x) + "," + std::to_string(inspection_.y);
    if (key == inspectedFor_) return;
    inspectedFor_ = key;
    inspection_.surface = false;
    inspection_.lights.clear();
    if (!a || !a->hasImages() || !a->lights) return;
    std::optional<glm::dvec3> p = surfaceAt(a->camera, a->run->depth, inspection_.x, inspection_.y);
    if (!p) return;
    inspection_.surface = true;
    inspection_.lights = lightsReaching(*a->lights, *p);
}

Camera& ViewerApp::userCamera() {
    if (state_.cameraFromScene) {
        state_.camera = sceneCamera_;
        state_.cameraFromScene = false;
    }
    return state_.camera;
}

void ViewerApp::moveCamera(float forward, float right, float up) {
    if (!hasSceneCamera_) return;
    pauseForUserMove();
    Camera& c = userCamera();
    float step = moveStep(c);
    flyMove(c, forward * step, right * step, up * step);
}
void ViewerApp::turnCamera(float yaw, float pitch) {
    if (!hasSceneCamera_) return;
    pauseForUserMove();
    flyTurn(userCamera(), yaw, pitch);
}
void ViewerApp::orbitCamera(float yaw, float pitch) {
    if (!hasSceneCamera_) return;
    pauseForUserMove();
    orbit(userCamera(), yaw, pitch);
}
void ViewerApp::resetCamera() {
    pauseForUserMove();
    state_.cameraFromScene = true;
    state_.camera = sceneCamera_;
}

void ViewerApp::frame() {
    takeOutcomes();
    advancePath();
    recompose();
    handleSceneMouse();
    drawPanels();
    submitJobs();
    measureAgainstReference();
    recompose();
}

} // namespace tp::view
