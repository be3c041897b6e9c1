#pragma once
// The steps of a run that runRenderer and RendererSession share (frame_runner.cpp): internal
// to core/runner.
#include "core/runner/frame_runner.h"

namespace tp {

class GpuProfiler;
class PassStatistics;

namespace detail {

// A pipeline's own failure as one line naming it, so the other pipelines still run:
// RendererError (this configuration cannot be built) or GraphError (its declarations disagree
// with each other or with its shaders, or it records an attachment it did not declare).
template <class Step> Status pipelineStep(const RendererEntry& entry, Step&& step) {
    try {
        step();
    } catch (const RendererError& e) {
        return Error{"pipeline " + entry.name + ": " + e.what()};
    } catch (const GraphError& e) {
        return Error{"pipeline " + entry.name + ": " + e.what()};
    }
    return {};
}

// `statistics` null: no pipeline-statistics query is recorded (--pass-statistics off).
void recordFrame(VkCommandBuffer cmd, FrameGraph& graph, GpuProfiler& profiler,
                 PassStatistics* statistics);
// Warm-up then timed frames of the one recording; the profiler keeps the timed ones, `energy`
// gets their energy (RunOptions::energy; frames added past them to lengthen its window are not
// timed). `after` (may be null) is submitted in the last frame's batch, after it. Returns how
// many warm-up frames ran.
uint32_t submitFrames(GpuContext& ctx, VkCommandBuffer cmd, GpuProfiler& profiler,
                      const RunOptions& options, FrameEnergy& energy,
                      VkCommandBuffer after = VK_NULL_HANDLE);
// What a report needs from the frames just run (without RunOptions::readback: no images, no
// per-pass work; `statistics` null: no counts, so no efficiency either).
RunResult collectResult(GpuContext& ctx, const SceneGpu& scene, const RendererEntry& entry,
                        const RenderSettings& settings, PlannedRenderer& planned,
                        GpuProfiler& profiler, const PassStatistics* statistics,
                        const RunOptions& options);

} // namespace detail
} // namespace tp
