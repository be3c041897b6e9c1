#pragma once
// Runs one renderer on the shared scene: plan, compile, prepare, record once, submit
// warm-up frames then timed frames, read back the standard outputs (planRenderer alone:
// the plan without running it). Everything a report
// needs comes back in RunResult; nothing here knows which renderer ran.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/calibrate/efficiency.h"
#include "core/calibrate/pass_work.h"
#include "core/energy/energy_meter.h"
#include "core/energy/frame_energy.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/ledger.h"
#include "core/gpu/profiler.h"
#include "core/image/image.h"
#include "core/renderer/renderer.h"

namespace tp {

struct RunOptions {
    uint32_t warmupFrames = 1;
    uint32_t timedFrames = 3;
    // Called after each submitted frame (index from 0 over warm-up + timed), for progress.
    std::function<void(uint32_t frame, uint32_t total, double frameMs)> onFrame;
    // The device's measured ceilings (docs/efficiency.md): with them, every pass is placed
    // against them (RunResult::efficiency). Null: not placed.
    std::shared_ptr<const CeilingRates> ceilings;
    // false: timings and counters only, no images (a camera path's timing pass: nothing on the
    // CPU between one view's frames and the next's); the work counts and placement need them.
    bool readback = true;
    // With readback: false reads everything but the hdr and depth images (the viewer shows its
    // renderers' images where they are: RendererSession::readImages reads them later if asked).
    bool images = true;
    // With images: false reads the depth alone (the caller holds this frame's hdr already: the
    // viewer's worker on a device of its own read it to show the view first).
    bool hdr = true;
    // The device's energy counter (core/runner/device_energy.h): read around the timed frames
    // (RunResult::energy). Null: not measured (the result's reason says so).
    std::shared_ptr<EnergySource> energy;
    // A window shorter than the counter allows runs the same frames on until it is long enough
    // (core/energy/energy_window.h); false (the viewer, which cannot wait): the energy is left
    // out with that reason.
    bool extendEnergyWindow = true;
    // Recorded (RendererSession::render) into a command buffer submitted in the batch of the
    // last frame, with the frame's hdr image (TRANSFER_SRC_OPTIMAL by then): the viewer's copy
    // of a view for its display, without a submission and a wait of its own (issue 42).
    std::function<void(VkCommandBuffer, const Image& hdr)> afterLastFrame;
};

struct RunResult {
    std::string renderer;
    uint32_t msaa = 1; // samples per pixel it ran with
    // The knobs this renderer declared, with the values it ran with (defaults filled in).
    std::vector<std::pair<Knob, std::string>> knobs;
    ImageRGBA hdr;
    ImageR32 depth;
    std::vector<TimingStats> timings; // "frame" first, then each live pass in order
    std::vector<LedgerEntry> memory;  // this renderer's allocations (owner == renderer name)
    RendererStats stats;
    std::vector<std::string> passes;       // recorded
    std::vector<std::string> culledPasses; // declared but not recorded (outputs unused)
    std::vector<DebugImage> debugImages;   // only with settings.debug
    std::vector<PassWork> work;            // per live pass, in recording order (docs/efficiency.md)
    std::optional<FrameEfficiency> efficiency; // with RunOptions::ceilings
    FrameEnergy energy; // the timed frames' energy, or the reason it is unknown
    // The per-pass pipeline statistics were counted; else `statisticsWhy` says why not
    // (--pass-statistics off, or a device without the query).
    bool statisticsCollected = false;
    std::string statisticsWhy;
};

// A renderer built for the scene and planned, its frame graph compiled (resources exist), not
// yet prepared: what `triptych info` prints, and the first half of runRenderer.
struct PlannedRenderer {
    std::unique_ptr<Renderer> renderer;
    std::unique_ptr<FrameGraph> graph; // destroyed before the renderer, as it was built after it
    ResourceHandle hdr, depth;         // the standard outputs it exports
};

// --shadows: plans which lights cast shadows for the scene's current view and lights
// (planShadows, core/passes/shadow_planner.h) and gives the plan to the scene
// (SceneGpu::setShadows). Every render calls it after the view is set; a caller that changes
// the view itself and needs the scene's state before rendering (a camera path) calls it too.
// Throws ShadowError when the budget cannot hold the lights.
void planSceneShadows(GpuContext& ctx, SceneGpu& scene, const ShadowSettings& settings);

// Sets the scene's view and its shadow plan (planSceneShadows), creates the renderer
// (createRenderer: the one check of its knobs and the sample count, defaults filled in), plans
// it, checks that it exports "hdr" and "depth", compiles the graph. Error: the sample count ("--msaa N: not supported by DEVICE"), a knob or
// the renderer's plan refused, as one line naming the pipeline.
Result<PlannedRenderer> planRenderer(GpuContext& ctx, SceneGpu& scene, const RendererEntry& entry,
                                     const SceneFeatures& features, const RenderSettings& settings);

// planRenderer, then prepare, record once, submit, read back. Error: as planRenderer, or the
// renderer's prepare or recording refused (one line each). A Vulkan failure throws GpuError.
Result<RunResult> runRenderer(GpuContext& ctx, SceneGpu& scene, const RendererEntry& entry,
                              const SceneFeatures& features, const RenderSettings& settings,
                              const RunOptions& options);
// runRenderer with a Vulkan failure as one more error ("Vulkan error: ..."), not thrown: the
// commands that run several pipelines (compare, sweep, stress) record it and go on.
Result<RunResult> tryRunRenderer(GpuContext& ctx, SceneGpu& scene, const RendererEntry& entry,
                                 const SceneFeatures& features, const RenderSettings& settings,
                                 const RunOptions& options);

// A counter of the run (RendererStats::counters), or `fallback` where the renderer does not
// count it (a pipeline that cannot drop a light counts no drops).
double counterValue(const RunResult& run, const std::string& name, double fallback = 0.0);
// The median GPU time of the run's whole frame ("frame" timing), 0 when it has none.
double frameMedianMs(const RunResult& run);

} // namespace tp
