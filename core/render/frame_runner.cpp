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
                                     VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS;
    }

  private:
    GpuContext& ctx_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
};

void recordFrame(VkCommandBuffer cmd, FrameGraph& graph, GpuProfiler& profiler, InvocationCounter& counter) {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
    profiler.beginFrame(cmd);
    counter.begin(cmd);
    graph.record(cmd, &profiler);
    counter.end(cmd);
    profiler.endFrame(cmd);
    VK_CHECK(vkEndCommandBuffer(cmd));
}

} // namespace

Result<RunResult> runRenderer(GpuContext& ctx, SceneGpu& scene, const RendererEntry& entry,
                              const SceneFeatures& features, const RenderSettings& settings,
                              const RunOptions& options) {
    if (Status s = checkSampleCount(ctx, settings.msaa); !s) return Error{s.error()};
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
    InvocationCounter invocations(ctx);
    VkCommandBuffer cmd = ctx.allocateCommandBuffer();
    try {
        recordFrame(cmd, graph, profiler, invocations);
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
    result.msaa = settings.msaa;
    for (const Knob& k : entry.knobs) result.knobs.push_back({k, resolved.text(k.name)});
    result.timings = profiler.stats();
    result.hdr = readbackColor(ctx, graph.image(hdr));
    result.depth = readbackDepth(ctx, graph.image(depth));
    renderer->collectStats(graph);
    if (settings.debug) result.debugImages = renderer->debugImages(graph);
    result.stats = renderer->stats();
    if (uint64_t n = 0; invocations.read(n)) {
        result.stats.counters.push_back({"fragment_shader_invocations", double(n)});
        result.stats.counters.push_back(
            {"fragment_invocations_per_pixel", double(n) / double(settings.width * settings.height)});
    }
    result.memory = ctx.ledger.entriesOf(entry.name);
    result.passes = graph.livePasses();
    result.culledPasses = graph.culledPasses();
    return result;
}

} // namespace tp
