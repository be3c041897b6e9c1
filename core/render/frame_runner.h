#pragma once
// Runs one renderer on the shared scene: plan, compile, prepare, record once, submit
// warm-up frames then timed frames, read back the standard outputs. Everything a report
// needs comes back in RunResult; nothing here knows which renderer ran.
#include <functional>
#include <string>
#include <vector>

#include "core/gpu/ledger.h"
#include "core/gpu/profiler.h"
#include "core/image/image.h"
#include "core/render/renderer.h"

namespace tp {

struct RunOptions {
    uint32_t warmupFrames = 1;
    uint32_t timedFrames = 3;
    // Called after each submitted frame (index from 0 over warm-up + timed), for progress.
    std::function<void(uint32_t frame, uint32_t total, double frameMs)> onFrame;
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
};

// Error: a knob, the sample count or the renderer's plan refused (one line each).
Result<RunResult> runRenderer(GpuContext& ctx, SceneGpu& scene, const RendererEntry& entry,
                              const SceneFeatures& features, const RenderSettings& settings,
                              const RunOptions& options);

} // namespace tp
