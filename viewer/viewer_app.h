#pragma once
// The viewer itself, independent of where its frames go (a window or the offscreen target):
// the state, the two background workers (the pipelines; the reference), what each change
// must rebuild, the composed scene area, and the ImGui panels drawn from the registry and
// the knob schema. The window and the headless script runner both drive this one class, so
// the tests exercise the code a user sees.
#include <chrono>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/calibrate/calibration_file.h"
#include "core/gpu/context.h"
#include "core/image/metrics.h"
#include "viewer/composite.h"
#include "viewer/exporter.h"
#include "viewer/gpu_composite.h"
#include "viewer/path_player.h"
#include "viewer/render_worker.h"
#include "viewer/view_state.h"

namespace tp::view {

struct ViewerOptions {
    ViewState initial;
    ContextOptions context;    // each worker opens its own device with these
    uint32_t timedFrames = 1;  // frames per render (the timing graph's samples)
    uint32_t panelWidth = 420; // the control panel, right of the scene area
    std::string exe;           // this program, for export (it runs `render` / `compare`)
    // --calibration FILE: every pass placed against its ceilings in the numbers panel
    // (docs/efficiency.md); null: not placed.
    std::shared_ptr<const CeilingFile> calibration;
    bool passStatistics = true; // --pass-statistics: off records no pipeline-statistics query
    // --camera-path / --light-motion: the path to play (initial.lightMotion moves the lights);
    // not loaded: neither was given. --path-frames: the views of a glTF path the panel loads.
    PathPlayer path;
    uint32_t pathFrames = 120;
    // --share-device: the renderers on the UI's device, their images composed where they are
    // (gpu_composite.h). "auto": where the device has a second queue for them (a GPU; lavapipe
    // has one queue, which the UI's frames would wait behind a render on); "on", "off".
    std::string shareDevice = "auto";
};

// A finished render of one pipeline, as the UI keeps it.
struct Shown {
    std::string pipeline;
    std::string key; // renderKey (pipelines) or referenceKey (the reference) it was made for
    std::string error;
    std::shared_ptr<const RunResult> run;
    double buildMs = 0;
    uint64_t serial = 0; // unique per image: what the composite and metrics were made from
    std::shared_ptr<const std::vector<Light>> lights; // what it was rendered with
    Camera camera;
    bool planned = false; // the renderer was planned for it (else it followed a camera move)
    double updateMs = 0;  // CPU: following the camera move (RendererSession), when it moved
    // Shared device: the image where the UI composes it from; the run's hdr and depth are
    // then empty until read back (hasImages).
    std::shared_ptr<const DisplayImage> display;
    double framesMs = 0; // PipelineImage's
    RendererSession::Steps steps;
    bool hasImages() const { return run && run->hdr.width > 0; }
};

// The median GPU time of its frame (0: none).
double frameGpuMs(const Shown* s);

// Per-pass GPU times of the last frames of one pipeline (the graph and its median/min/max).
struct TimingHistory {
    std::map<std::string, std::deque<double>> passes; // name -> last kHistory times (ms)
    std::vector<std::string> order;                   // "frame" first, then passes
    std::deque<double> wallMs; // the last kHistory renders' wall times (plan, frames, readback)
    static constexpr size_t kHistory = 64;
    void add(const std::vector<TimingStats>& timings, double renderWallMs);
};

// A's error against the reference, kept after the view moves on (shown marked stale, with the
// view it is of, until the reference of the new view is done).
struct KeptError {
    ErrorReport hdr, display;
    std::string view; // which view: "path view 3 of 8", or the camera's eye and target
};

// The pixel inspector's readout for the pixel under the cursor.
struct Inspection {
    bool valid = false;
    uint32_t x = 0, y = 0;
    float a[4] = {}, b[4] = {};
    bool surface = false;         // A shows a surface there (not the sky)
    std::vector<uint32_t> lights; // lights reaching that surface (pixel_lights.h)
};

class ViewerApp {
  public:
    ViewerApp(GpuContext& uiContext, ViewerOptions options);
    ~ViewerApp();

    // One UI frame, between ImGui::NewFrame() and ImGui::Render(): takes finished renders,
    // submits what the state now needs, handles the mouse over the scene area, draws the panels.
    void frame();
    // The scene area, recomposed when its inputs changed; sceneDirty() until taken.
    const Composite& scene() const { return composite_; }
    // The UI's target is BGRA (a swapchain): a GPU composite writes that order.
    void setTargetBgra(bool bgra) { targetBgra_ = bgra; }
    // The renderers share the UI's device (--share-device), and the images read back so far
    // (each a hdr and depth of a shared-device render; 0 without one).
    bool sharesDevice() const { return shared_; }
    uint64_t imageReadbacks() const { return imageReadbacks_; }
    bool takeSceneDirty();
    uint32_t panelWidth() const { return options_.panelWidth; }

    ViewState& state() { return state_; }
    const ViewState& const_state() const { return state_; }
    // Nothing rendering or queued, and (when enabled) the reference of this view present.
    bool settled() const;
    // Actions shared by the panels, the keys and the script runner.
    void toggleFlip() {
        state_.flip = !state_.flip;
        sceneInputsChanged_ = true;
    }
    void setSplit(float share);
    void requestReference() { referenceRequested_ = true; }
    // Camera moves (scene units are steps of moveStep; angles in degrees). The first move
    // takes over the scene's camera.
    Camera& userCamera();
    void moveCamera(float forward, float right, float up);
    void turnCamera(float yaw, float pitch);
    void orbitCamera(float yaw, float pitch);
    void resetCamera();
    // A frame after a camera load or bookmark: the camera given, no longer the scene's.
    void setCamera(const Camera& c) {
        pauseForUserMove();
        state_.camera = c;
        state_.cameraFromScene = false;
    }
    // Bookmarks: one camera file each (core/camera/camera_file.h), or a list of them (load
    // takes the first). Errors go to the status line.
    void saveBookmark(const std::string& path);
    void loadBookmark(const std::string& path);
    // A camera path recorded by flying (docs/camera_paths.md): the current camera as the next
    // key; the keys as a triptych.camera_path/1 file (catmull-rom) of `frames` views, 0: 30 per
    // segment. `--camera-path` of render, compare and sweep reads it.
    void addPathKey();
    void savePath(const std::string& path, uint32_t frames = 0);
    size_t pathKeys() const { return pathKeys_.size(); }
    // Playing a path (path_player.h; path_play.cpp): a camera path file (JSON or glTF, the
    // reader of --camera-path) replaces the one playing, at its view 0, paused; errors go to
    // the status line. A move of the camera by the user pauses a playing camera path.
    void loadPath(const std::string& file);
    void setPlaying(bool playing);
    void togglePlay() { setPlaying(!player_.playing); }
    void seekPath(uint32_t view);
    const PathPlayer& path() const { return player_; }
    void setPathLoop(bool loop) { player_.loop = loop; }
    // `render` of A and `compare` of A and B into DIR/render and DIR/compare (exporter.h).
    void startExport(const std::string& dir);
    std::string exportStatus() const { return exporter_.status(); }
    bool exporting() const { return exporter_.busy(); }
    // The scene's camera has arrived (camera moves before it would move a default camera).
    bool sceneLoaded() const { return hasSceneCamera_; }
    const Inspection& inspection() const { return inspection_; }
    const std::string& lastError() const { return error_; }
    // Render statistics for scripts and the benchmark.
    const Shown* shownA() const;
    const Shown* shownB() const;
    double lastRenderMs() const { return lastRenderMs_; }
    // From the UI's submission of the view's job to the UI taking its image (what the user waits
    // for: the worker's time, a wait behind its previous job, the hand-over).
    double lastViewLatencyMs() const { return lastLatencyMs_; }
    const std::optional<ErrorReport>& errorVsReference() const { return errorVsReference_; }
    // The last error measured against a reference, of this view (fresh) or an earlier one.
    const std::optional<KeptError>& keptError() const { return keptError_; }
    bool keptErrorStale() const { return !errorVsReference_; }
    const TimingHistory* history(const std::string& pipeline) const;
    const std::vector<LedgerEntry>& sceneMemory() const { return sceneMemory_; }
    bool referenceStale() const;
    const std::string& deviceName() const { return deviceName_; }
    bool supportsMsaa(uint32_t samples) const { return (sampleCounts_ & samples) != 0; }
    // Stops the workers; their devices' validation messages.
    std::vector<std::string> stop();

  private:
    friend struct Panels;
    void takeOutcomes();
    void submitJobs();
    void recompose();
    void handleSceneMouse();
    void measureAgainstReference();
    void inspectLights();
    void drawPanels(); // ui_panels.cpp
    const Shown* shownFor(const std::string& pipeline) const;
    void showPathView(); // the state takes the play head's camera and lights frame
    void advancePath();  // a playing head moves on once its view's images are shown
    bool pathViewShown() const;
    void pauseForUserMove();
    std::string viewLabel() const;

    Shown makeShown(PipelineImage& image, const RenderOutcome& o); // outcomes.cpp
    void takeOutcome(RenderOutcome& o);
    void takeCollected(RenderOutcome& o);
    void keepLastCollected(RunResult& run, const std::string& pipeline) const;
    bool wantImages() const;
    Composite composeOnGpu(const CompositeInput& in, const Shown* a, const Shown* b, uint32_t w,
                           uint32_t h);

    GpuContext& ui_;
    bool shared_ = false;
    bool targetBgra_ = false;
    std::unique_ptr<GpuComposite> gpuComposite_;
    bool submittedImages_ = false;
    bool inspecting_ = false; // the cursor rests on the scene area: the inspector reads pixels
    uint64_t imageReadbacks_ = 0;
    ViewerOptions options_;
    ViewState state_;
    std::string deviceName_;
    uint32_t sampleCounts_ = 1;
    std::unique_ptr<RenderWorker> worker_, referenceWorker_;
    uint64_t nextJob_ = 1;
    std::string submittedKey_, submittedReferenceKey_;
    std::vector<std::string> submittedPipelines_;
    std::map<std::string, Shown> shown_; // latest finished image per pipeline
    std::optional<Shown> reference_;
    std::map<std::string, TimingHistory> history_;
    std::optional<ErrorReport> errorVsReference_, errorVsReferenceDisplay_;
    std::optional<KeptError> keptError_;
    PathPlayer player_;
    std::string measuredFor_;
    std::string lastRebuilt_;
    double lastRenderMs_ = 0, lastSceneMs_ = 0, lastLatencyMs_ = 0;
    std::map<uint64_t, std::chrono::steady_clock::time_point> submittedAt_; // by job id
    std::vector<LedgerEntry> sceneMemory_;
    size_t lightCount_ = 0, triangleCount_ = 0;
    Camera sceneCamera_;
    bool hasSceneCamera_ = false;
    Composite composite_;
    bool sceneDirty_ = true, sceneInputsChanged_ = true;
    std::string composedFor_;
    bool referenceRequested_ = false;
    bool dragging_ = false;
    Inspection inspection_;
    std::string inspectedFor_;
    std::string error_;
    std::string exportStatus_;
    std::string exportDir_ = "view_export";
    std::string bookmarkPath_ = "bookmark.json";
    std::string pathFile_ = "path.json";
    std::vector<Camera> pathKeys_;
    ViewState draft_; // what the panels' text fields edit until "Apply" (lights, scene, size)
    float autoEv_ = 0.0f;
    uint64_t autoEvFor_ = 0;
    uint64_t nextSerial_ = 1;
    Exporter exporter_;
};

} // namespace tp::view
