#pragma once
// A background renderer with its own Vulkan device, scene copy and thread, so the UI never
// waits on a rebuild or on the reference (seconds on lavapipe). The UI submits jobs; a job
// not yet started is replaced by a newer one (only the latest view matters), and the UI
// takes finished outcomes when it draws its next frame.
//
// Rebuilds only what a job's state needs (view_state.h): a new scene key reloads and uploads
// the scene, a new lights key regenerates and uploads only the lights, a new plan key (lights,
// resolution, MSAA, knobs, overlays) plans the renderers again; a camera move, or a frame of
// moving lights (same count), only follows the view: each pipeline's RendererSession
// (core/runner/render_session.h) is kept between jobs and updates its per-view data in place.
#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/calibrate/calibration_file.h"
#include "core/gpu/context.h"
#include "core/runner/frame_runner.h"
#include "core/runner/render_session.h"
#include "core/scene/light_motion.h"
#include "viewer/view_state.h"

namespace tp::view {

struct RenderJob {
    uint64_t id = 0;
    ViewState state;
    std::vector<std::string> pipelines;
    bool debug = false; // renderers export their debug images (overlays)
    std::string key;    // renderKey/referenceKey of `state`: tags the outcome
    uint32_t timedFrames = 1;
    std::shared_ptr<const CeilingFile> calibration; // used when it is this device's
    bool passStatistics = true; // --pass-statistics (RenderSettings::passStatistics)
    // The worker shares the UI's device (RenderWorker's `share`): each image is copied into a
    // display image the UI composes from, and the outcome is given as soon as it is there;
    // the counters follow in a second one. `images`: the hdr and depth are read back in it
    // too (the reference's error, the inspector, overlays); without a shared device always.
    bool images = true;
};

// A renderer's hdr image copied where the UI's composite samples it (SHADER_READ_ONLY_OPTIMAL,
// on the shared device): the renderer's own is overwritten by its next view while the UI may
// still show this one. Held by the outcome and the UI; the worker reuses one nobody else holds.
struct DisplayImage {
    Image image;
};

struct PipelineImage {
    std::string pipeline;
    std::string error; // empty: `run` holds the result
    RunResult run;
    double buildMs = 0;    // wall time of the whole run: plan (if any), frames, readback
    bool planned = false;  // this job planned the renderer (a new session or a replan)
    std::shared_ptr<const DisplayImage> display; // the shared device's copy (else null)
    double framesMs = 0;  // wall time of the session's render (update, frames, what it read)
    RendererSession::Steps steps; // how that split
    double updateMs = 0;   // CPU: following the new view (updateView + recording), if it moved
    // The first of two outcomes (RenderWorker's showFirst): `run` holds the timings, the view's
    // counters and (without `display`) the hdr; the rest follows in the collected outcome.
    bool partial = false;
};

struct RenderOutcome {
    uint64_t id = 0;
    std::string key;
    std::string error;   // the scene failed to load or the device failed: shown, viewer stays open
    std::string rebuilt; // "scene", "lights", "renderer" or "view": the widest rebuild this job
                         // needed ("view": the camera moved, the renderers followed in place)
    double sceneMs = 0;  // scene load + upload, or light regeneration + upload
    double totalMs = 0;  // the whole job
    std::vector<PipelineImage> images;
    std::vector<LedgerEntry> sceneMemory; // the shared scene upload (owner "scene")
    Camera sceneCamera;                   // the scene's own camera (for "reset camera")
    size_t lightCount = 0;
    std::shared_ptr<const std::vector<Light>> lights; // the job's lights (the inspector's)
    Camera camera;                                    // the camera it rendered with
    size_t triangleCount = 0;
    // The second outcome of a job on a shared device (RenderWorker::collectLater): the same
    // images with their whole runs (the first carries the timings and the frames' counters).
    bool collected = false;
};

// How long a shared-device worker waits, after showing a view, for the next one before it reads
// the view's counters (and images) back: a camera in motion is not slowed by them.
constexpr int kStatsGraceMs = 20;

class RenderWorker {
  public:
    // share: the UI's context, whose device the worker renders on (its second queue where the
    // device has one, GpuContext::share); null: a device of its own. showFirst: each view's
    // outcome goes as soon as its image is there (the display copy, or on a device of its own
    // the hdr read back alone), its counters and the rest in a second outcome (always so with
    // `share`; the reference's worker reads everything at once).
    RenderWorker(ContextOptions options, std::string label, GpuContext* share = nullptr,
                 bool showFirst = false);
    ~RenderWorker();
    RenderWorker(const RenderWorker&) = delete;
    RenderWorker& operator=(const RenderWorker&) = delete;

    void submit(RenderJob job);
    std::optional<RenderOutcome> take(); // the oldest outcome not yet taken
    bool idle() const; // nothing queued, running, or finished and not yet taken
    const std::string& label() const { return label_; }
    // After the destructor's join would be too late: stops the thread, returns its context's
    // validation messages (empty without --validate).
    std::vector<std::string> stop();

  private:
    void loop();
    RenderOutcome runJob(const RenderJob& job);
    void publish(RenderOutcome outcome);
    RunOptions runOptionsFor(const RenderJob& job) const;
    RunOptions withEnergy(const std::string& pipeline, const RenderJob& job, RunOptions options) const;
    std::optional<RenderOutcome> collectLater(const RenderJob& job, const RenderOutcome& shown);
    std::shared_ptr<DisplayImage> freeDisplay(const ImageDesc& hdr);
    static void recordDisplayCopy(VkCommandBuffer cmd, const Image& hdr, const Image& dst);
    void prepareScene(const RenderJob& job, RenderOutcome& out);
    void moveLights(const ViewState& s);
    PipelineImage renderPipeline(const std::string& name, const RenderJob& job,
                                 const RenderSettings& settings, const RunOptions& options);

    ContextOptions options_;
    std::string label_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<RenderJob> pending_;
    std::deque<RenderOutcome> done_;
    GpuContext* share_ = nullptr;
    bool showFirst_ = false;

    bool running_ = false, quit_ = false;
    std::vector<std::string> messages_;
    std::thread thread_;

    // Owned by the worker thread only.
    std::vector<std::shared_ptr<DisplayImage>> displays_; // the worker's, reused when free
    std::map<std::string, double> lastFrameMs_;           // by pipeline: its last frame's GPU time
    std::unique_ptr<GpuContext> ctx_;
    std::string contextError_;
    // The device's energy counter (core/runner/device_energy.h): a render's window is its timed
    // frames only (a window too short says so: the viewer does not wait to extend it).
    std::shared_ptr<EnergySource> energy_;
    std::unique_ptr<Scene> scene_;
    std::unique_ptr<SceneGpu> gpuScene_;
    std::vector<Light> sceneLights_; // the scene file's own lights
    Camera sceneCamera_;             // and its own camera (the user's replaces it per job)
    std::string sceneKey_, lightsKey_;
    // --light-motion: the lights before they move, the plan of their motion (kept while the
    // start lights and the motion stay), and motionKey of the lights now uploaded.
    std::vector<Light> startLights_;
    std::unique_ptr<LightMotionPlan> motionPlan_;
    std::string motionPlanFor_, movedKey_;
    struct Planned {
        std::string key; // planKey of the state it was planned for
        std::unique_ptr<RendererSession> session;
    };
    std::map<std::string, Planned> sessions_; // by pipeline: the current job's pipelines only
};

} // namespace tp::view
