#pragma once
// Plan once, render many views (issue: the camera moves). A renderer is planned for (scene,
// resolution, MSAA, settings, light count); the camera and the lights' positions are per-view
// inputs: the caller changes them on the SceneGpu (Scene::camera then setView, or setLights
// with the same count) and calls render() again. Before its frames, render() brings the
// renderer to the new view with Renderer::updateView (the contract's step 6), records again,
// and measures that CPU work; where the renderer cannot update (the view outgrew a list, the
// light count or spot presence changed) it plans the renderer again and counts the replan.
// runRenderer is a session that renders once.
#include <memory>

#include "core/gpu/pipelines.h"
#include "core/runner/frame_runner.h"

namespace tp {

class GpuProfiler;
class PassStatistics;

class RendererSession {
  public:
    // planRenderer + prepare; the errors are runRenderer's.
    static Result<std::unique_ptr<RendererSession>> create(GpuContext& ctx, SceneGpu& scene,
                                                           const RendererEntry& entry,
                                                           const SceneFeatures& features,
                                                           const RenderSettings& settings);
    ~RendererSession();
    RendererSession(const RendererSession&) = delete;
    RendererSession& operator=(const RendererSession&) = delete;

    // The scene's current camera and lights: updated to (or planned again for) first, then
    // options' frames, then read back (RunOptions::readback false: timings and counters only).
    // After a view change the result's counters carry view_update_ms (CPU: the update and the
    // new recording), view_updates and view_replans (over the session so far).
    Result<RunResult> render(const RunOptions& options);

    const std::string& name() const;
    // Where the last render's wall time went (the viewer's benchmark: what a new view costs
    // beyond its GPU frame).
    struct Steps {
        double followMs = 0;   // the view update and the new recording (or a plan)
        double framesMs = 0;   // submitting the frames and waiting for them, the timestamps, energy
        double energyMs = 0;   // of which reading the energy counter (FrameEnergy::readMs)
        double overflowMs = 0; // reading whether a capacity overflowed (and any replan's frames)
        double collectMs = 0;  // what collectResult read (nothing but timings without readback)
    };
    const Steps& lastSteps() const { return steps_; }
    // The last render's hdr image, on the device (TRANSFER_SRC_OPTIMAL until the next render),
    // and its hdr and depth read back into `result` (a render with RunOptions::images false).
    const Image& hdrImage() const;
    // What a render with RunOptions::readback false left out (the counters, memory, work,
    // placement; the images with options.images), read from its frames now, while nothing
    // has run since: the viewer shows a view first and reads this after (or not at all when
    // the next view is already waiting).
    RunResult collect(const RunOptions& options);
    uint32_t updates() const { return updates_; }
    uint32_t replans() const { return replans_; }

  private:
    RendererSession(GpuContext& ctx, SceneGpu& scene, const RendererEntry& entry,
                    const SceneFeatures& features, const RenderSettings& settings);
    Status plan();
    Status record();
    Status follow(double& updateMs); // the view changed since the last recording
    VkCommandBuffer recordAfter(const RunOptions& options);

    GpuContext& ctx_;
    SceneGpu& scene_;
    const RendererEntry& entry_;
    SceneFeatures features_;
    RenderSettings settings_;
    PlannedRenderer planned_;
    std::unique_ptr<GpuProfiler> profiler_;
    std::unique_ptr<PassStatistics> statistics_;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkCommandBuffer afterCmd_ = VK_NULL_HANDLE; // RunOptions::afterLastFrame's recording
    uint64_t generation_ = 0;   // SceneGpu::viewGeneration() the recording is for
    bool recorded_ = false;     // cmd_ holds a complete recording
    uint32_t lightCount_ = 0;   // planned for: a change needs a new plan
    std::vector<SpecConstant> sceneConstants_; // spot presence and texture count, planned for
    uint32_t updates_ = 0, replans_ = 0;
    Steps steps_;
};

} // namespace tp
