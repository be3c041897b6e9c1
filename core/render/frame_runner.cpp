#include "core/render/frame_runner.h"

#include <chrono>

#include "core/gpu/context.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/readback.h"
#include "core/gpu/vk_check.h"
#include "core/render/scene_gpu.h"

namespace tp {
namespace {

void recordFrame(VkCommandBuffer cmd, FrameGraph& graph, GpuProfiler& profiler) {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
    profiler.beginFrame(cmd);
    graph.record(cmd, &profiler);
    profiler.endFrame(cmd);
    VK_CHECK(vkEndCommandBuffer(cmd));
}

} // namespace

Result<RunResult> runRenderer(GpuContext& ctx, SceneGpu& scene, const RendererEntry& entry,
                              const SceneFeatures& features, const RenderSettings& settings,
                              const RunOptions& options) {
    RenderSettings resolved = settings;
    if (Status s = resolveKnobs(entry.knobs, resolved); !s) return Error{"pipeline " + entry.name + ": " + s.error()};
    scene.setView(settings.width, settings.height, settings.msaa);
    RendererCreateInfo info{ctx, scene, features, resolved};
    std::unique_ptr<Renderer> renderer;
    FrameGraph graph(ctx, entry.name, settings.width, settings.height);
    ResourceHandle hdr, depth;
    try {
        renderer = createRenderer(entry, info);
        renderer->plan(graph);
        hdr = graph.exported("hdr");
        depth = graph.exported("depth");
        if (!hdr.valid() || !depth.valid())
            return Error{"pipeline " + entry.name + " does not export both 'hdr' and 'depth'"};
        graph.compile();
        renderer->prepare(graph);
    } catch (const RendererError& e) {
        return Error{"pipeline " + entry.name + ": " + e.what()};
    } catch (const GraphError& e) {
        // A pass's declarations disagree with each other or with its shaders: a bug in
        // that pipeline, reported as one line so the other pipelines still run.
        return Error{"pipeline " + entry.name + ": " + e.what()};
    }

    GpuProfiler profiler(ctx, 64);
    VkCommandBuffer cmd = ctx.allocateCommandBuffer();
    try {
        recordFrame(cmd, graph, profiler);
    } catch (const GraphError& e) { // a pass records an attachment it did not declare
        ctx.freeCommandBuffer(cmd);
        return Error{"pipeline " + entry.name + ": " + e.what()};
    }
    const uint32_t total = options.warmupFrames + options.timedFrames;
    for (uint32_t f = 0; f < total; ++f) {
        auto start = std::chrono::steady_clock::now();
        ctx.submitAndWait(cmd);
        std::chrono::duration<double, std::milli> wall = std::chrono::steady_clock::now() - start;
        profiler.collect();
        if (f + 1 == options.warmupFrames) profiler.discardSamples();
        if (options.onFrame) options.onFrame(f, total, wall.count());
    }
    ctx.freeCommandBuffer(cmd);

    RunResult result;
    result.renderer = entry.name;
    for (const Knob& k : entry.knobs) result.knobs.push_back({k, resolved.text(k.name)});
    result.timings = profiler.stats();
    result.hdr = readbackColor(ctx, graph.image(hdr));
    result.depth = readbackDepth(ctx, graph.image(depth));
    renderer->collectStats(graph);
    if (settings.debug) result.debugImages = renderer->debugImages(graph);
    result.stats = renderer->stats();
    result.memory = ctx.ledger.entriesOf(entry.name);
    result.passes = graph.livePasses();
    result.culledPasses = graph.culledPasses();
    return result;
}

} // namespace tp
