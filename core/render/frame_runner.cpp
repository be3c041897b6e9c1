#include "core/render/frame_runner.h"

#include <chrono>

#include "core/gpu/context.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/readback.h"
#include "core/gpu/vk_check.h"
#include "core/render/scene_gpu.h"

namespace tp {
namespace {

// Counts the fragment-shader invocations of a whole frame (every pass) with a pipeline
// statistics query, where the device has them (lavapipe does): the measure of the MSAA
// shading rate (--msaa-shading pixel runs about one invocation per covered pixel and
// primitive, sample about one per covered sample).
class InvocationCounter {
  public:
    explicit InvocationCounter(GpuContext& ctx) : ctx_(ctx) {
        if (!ctx.caps.pipelineStatisticsQuery) return;
        VkQueryPoolCreateInfo ci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        ci.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
        ci.queryCount = 1;
        ci.pipelineStatistics = VK_QUERY_PIPELINE_STATISTIC_FRAGMENT_SHADER_INVOCATIONS_BIT;
        VK_CHECK(vkCreateQueryPool(ctx.device, &ci, nullptr, &pool_));
    }
    ~InvocationCounter() {
        if (pool_) vkDestroyQueryPool(ctx_.device, pool_, nullptr);
    }
    InvocationCounter(const InvocationCounter&) = delete;
    InvocationCounter& operator=(const InvocationCounter&) = delete;

    void begin(VkCommandBuffer cmd) {
        if (!pool_) return;
        vkCmdResetQueryPool(cmd, pool_, 0, 1);
        vkCmdBeginQuery(cmd, pool_, 0, 0);
    }
    void end(VkCommandBuffer cmd) {
        if (pool_) vkCmdEndQuery(cmd, pool_, 0);
    }
    // The last submitted frame's count; false without the query.
    bool read(uint64_t& out) {
        if (!pool_) return false;
        return vkGetQueryPoolResults(ctx_.device, pool_, 0, 1, sizeof(out), &out, sizeof(out),
                                     VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) ==
               VK_SUCCESS;
    }

  private:
    GpuContext& ctx_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
};

void recordFrame(VkCommandBuffer cmd, FrameGraph& graph, GpuProfiler& profiler,
                 InvocationCounter& counter) {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
    profiler.beginFrame(cmd);
    counter.begin(cmd);
    graph.record(cmd, &profiler);
    counter.end(cmd);
    profiler.endFrame(cmd);
    VK_CHECK(vkEndCommandBuffer(cmd));
}

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

// Warm-up then timed frames of the one recording; the profiler keeps the timed ones.
void submitFrames(GpuContext& ctx, VkCommandBuffer cmd, GpuProfiler& profiler,
                  const RunOptions& options) {
    const uint32_t total = options.warmupFrames + options.timedFrames;
    for (uint32_t f = 0; f < total; ++f) {
        auto start = std::chrono::steady_clock::now();
        ctx.submitAndWait(cmd);
        std::chrono::duration<double, std::milli> wall = std::chrono::steady_clock::now() - start;
        profiler.collect();
        if (f + 1 == options.warmupFrames) profiler.discardSamples();
        if (options.onFrame) options.onFrame(f, total, wall.count());
    }
}

// What a report needs from the frames just run.
RunResult collectResult(GpuContext& ctx, const RendererEntry& entry, const RenderSettings& settings,
                        PlannedRenderer& planned, GpuProfiler& profiler,
                        InvocationCounter& invocations) {
    FrameGraph& graph = *planned.graph;
    RunResult result;
    result.renderer = entry.name;
    result.msaa = settings.msaa;
    // createRenderer checked every value: each knob's is the given one or its default.
    for (const Knob& k : entry.knobs)
        result.knobs.push_back({k, k.valueIn(settings.knobs)});
    result.timings = profiler.stats();
    result.hdr = readbackColor(ctx, graph.image(planned.hdr));
    result.depth = readbackDepth(ctx, graph.image(planned.depth));
    planned.renderer->collectStats(graph);
    if (settings.debug) result.debugImages = planned.renderer->debugImages(graph);
    result.stats = planned.renderer->stats();
    if (uint64_t n = 0; invocations.read(n)) {
        result.stats.counters.push_back({"fragment_shader_invocations", double(n)});
        result.stats.counters.push_back({"fragment_invocations_per_pixel",
                                         double(n) / double(settings.width * settings.height)});
    }
    result.memory = ctx.ledger.entriesOf(entry.name);
    result.passes = graph.livePasses();
    result.culledPasses = graph.culledPasses();
    return result;
}

} // namespace

Result<PlannedRenderer> planRenderer(GpuContext& ctx, SceneGpu& scene, const RendererEntry& entry,
                                     const SceneFeatures& features,
                                     const RenderSettings& settings) {
    // The count alone, without the pipeline's name: the CLI's line (checkSampleCount).
    if (Status s = checkSampleCount(ctx, settings.msaa); !s) return Error{s.error()};
    scene.setView(settings.width, settings.height, settings.msaa);
    PlannedRenderer planned;
    planned.graph = std::make_unique<FrameGraph>(ctx, entry.name, settings.width, settings.height);
    FrameGraph& graph = *planned.graph;
    bool exports = true;
    Status built = pipelineStep(entry, [&] {
        planned.renderer = createRenderer(entry, {ctx, scene, features, settings});
        planned.renderer->plan(graph);
        planned.hdr = graph.exported("hdr");
        planned.depth = graph.exported("depth");
        exports = planned.hdr.valid() && planned.depth.valid();
        if (exports) graph.compile();
    });
    if (!built) return Error{built.error()};
    if (!exports)
        return Error{"pipeline " + entry.name + " does not export both 'hdr' and 'depth'"};
    return planned;
}

Result<RunResult> runRenderer(GpuContext& ctx, SceneGpu& scene, const RendererEntry& entry,
                              const SceneFeatures& features, const RenderSettings& settings,
                              const RunOptions& options) {
    Result<PlannedRenderer> planned = planRenderer(ctx, scene, entry, features, settings);
    if (!planned) return Error{planned.error()};
    if (Status s = pipelineStep(entry, [&] { planned->renderer->prepare(*planned->graph); }); !s)
        return Error{s.error()};

    GpuProfiler profiler(ctx, 64);
    InvocationCounter invocations(ctx);
    VkCommandBuffer cmd = ctx.allocateCommandBuffer();
    if (Status s =
            pipelineStep(entry, [&] { recordFrame(cmd, *planned->graph, profiler, invocations); });
        !s) {
        ctx.freeCommandBuffer(cmd);
        return Error{s.error()};
    }
    submitFrames(ctx, cmd, profiler, options);
    ctx.freeCommandBuffer(cmd);
    return collectResult(ctx, entry, settings, *planned, profiler, invocations);
}

Result<RunResult> tryRunRenderer(GpuContext& ctx, SceneGpu& scene, const RendererEntry& entry,
                                 const SceneFeatures& features, const RenderSettings& settings,
                                 const RunOptions& options) {
    try {
        return runRenderer(ctx, scene, entry, features, settings, options);
    } catch (const GpuError& e) {
        return Error{std::string("Vulkan error: ") + e.what()};
    }
}

double counterValue(const RunResult& run, const std::string& name, double fallback) {
    for (const auto& [k, v] : run.stats.counters)
        if (k == name) return v;
    return fallback;
}

} // namespace tp
