#include "core/runner/frame_runner.h"

#include <algorithm>
#include <chrono>

#include "core/energy/energy_window.h"
#include "core/gpu/context.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/pass_statistics.h"
#include "core/gpu/readback.h"
#include "core/gpu/vk_check.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/shadow_planner.h"
#include "core/runner/frame_steps.h"
#include "core/runner/render_session.h"
#include "core/util/clock.h"

namespace tp {
namespace {

// A GPU lowers its clock within seconds of going idle (an H100: 1,980 to 345 MHz while compare
// measures the previous pipeline's error on the CPU) and takes about a second to raise it again:
// three warm-up frames of a few milliseconds are timed at a fraction of the clock. So on a GPU the
// warm-up goes on until it has run this long; a CPU device has no such clock.
constexpr double kGpuWarmupMs = 1000.0;
constexpr uint32_t kMaxWarmupFrames = 2000;

// Pixels whose depth is not the far plane (reverse-Z: 0): where geometry was shaded.
double coveredPixels(const ImageR32& depth) {
    return double(std::count_if(depth.r.begin(), depth.r.end(), [](float d) { return d > 0.0f; }));
}

std::vector<PassWork> countWork(const FrameGraph& graph, const std::vector<PassCounts>& counts,
                                const RunResult& result) {
    PassWorkInput in;
    in.decl = &graph.declarations();
    for (const PlannedPass& p : graph.plan().passes)
        in.livePasses.push_back(p.pass);
    in.resourceBytes = [&](uint32_t r) { return graph.contentBytes(r); };
    in.resourceSamples = [&](uint32_t r) { return uint32_t(graph.samples(r)); };
    in.counts = counts;
    in.lightWork = result.stats.lightWork;
    in.opWork = result.stats.opWork;
    in.coveredPixels = coveredPixels(result.depth);
    in.framePixels = double(graph.width()) * graph.height();
    return countPassWork(in);
}

// The share of the local lights that are spots: their evaluations meet the spot ceilings.
double spotShare(const std::vector<Light>& lights) {
    double local = 0, spots = 0;
    for (const Light& l : lights) {
        local += l.type != LightType::Directional;
        spots += l.type == LightType::Spot;
    }
    return local > 0 ? spots / local : 0.0;
}

// Whether the pipeline statistics were counted, and if not why: the report says so, never zeros.
void noteStatistics(RunResult& result, const PassStatistics* statistics) {
    result.statisticsCollected = statistics && statistics->available();
    if (result.statisticsCollected) return;
    result.statisticsWhy = statistics ? "the device has no pipelineStatisticsQuery"
                                      : "--pass-statistics off: no pipeline-statistics query was recorded";
    result.stats.leftOut.push_back({"pipeline statistics (each pass's primitive and fragment counts)",
                                    result.statisticsWhy});
    result.stats.leftOut.push_back({"efficiency (each pass against the device's ceilings)",
                                    "it needs the pipeline statistics: " + result.statisticsWhy});
}

} // namespace

namespace detail {

void recordFrame(VkCommandBuffer cmd, FrameGraph& graph, GpuProfiler& profiler,
                 PassStatistics* statistics) {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
    profiler.beginFrame(cmd);
    if (statistics) statistics->beginFrame(cmd);
    graph.record(cmd, &profiler, statistics);
    profiler.endFrame(cmd);
    VK_CHECK(vkEndCommandBuffer(cmd));
}

uint32_t submitFrames(GpuContext& ctx, VkCommandBuffer cmd, GpuProfiler& profiler,
                      const RunOptions& options, FrameEnergy& energy, VkCommandBuffer after) {
    const double minWarmupMs = options.warmupFrames > 0 && !ctx.isCpuDevice() ? kGpuWarmupMs : 0.0;
    const auto begin = std::chrono::steady_clock::now();
    EnergyWindow window(options.energy ? options.energy->meter.get() : nullptr,
                        options.energy ? options.energy->why : "not measured in this run");
    uint32_t warmup = options.warmupFrames;
    for (uint32_t f = 0; f < warmup + options.timedFrames; ++f) {
        if (f == warmup) window.begin(); // the first timed frame (warmup is final by now)
        auto start = std::chrono::steady_clock::now();
        const bool last = f + 1 == warmup + options.timedFrames; // warmup is final by then
        ctx.submitAndWait(cmd, last ? after : VK_NULL_HANDLE);
        std::chrono::duration<double, std::milli> wall = std::chrono::steady_clock::now() - start;
        profiler.collect();
        const bool lastWarmup = f + 1 == warmup;
        if (lastWarmup && msSince(begin) < minWarmupMs && warmup < kMaxWarmupFrames) ++warmup;
        else if (lastWarmup) profiler.discardSamples();
        if (options.onFrame) options.onFrame(f, warmup + options.timedFrames, wall.count());
    }
    // The same frames again, untimed, while the window is too short for the counter.
    uint32_t extended = 0;
    while (options.extendEnergyWindow && options.timedFrames > 0 && window.wantsMore(extended)) {
        ctx.submitAndWait(cmd);
        ++extended;
    }
    energy = window.end(options.timedFrames + extended, extended);
    return warmup;
}

RunResult collectResult(GpuContext& ctx, const SceneGpu& scene, const RendererEntry& entry,
                        const RenderSettings& settings, PlannedRenderer& planned, GpuProfiler& profiler,
                        const PassStatistics* statistics, const RunOptions& options) {
    FrameGraph& graph = *planned.graph;
    RunResult result;
    result.renderer = entry.name;
    result.msaa = settings.msaa;
    // createRenderer checked every value: each knob's is the given one or its default.
    for (const Knob& k : entry.knobs)
        result.knobs.push_back({k, k.valueIn(settings.knobs)});
    result.timings = profiler.stats();
    // A path's timing pass: nothing between one view's frames and the next's but the update
    // (no images, no counters read back; the session adds its own).
    if (!options.readback) return result;
    if (options.images) {
        if (options.hdr) result.hdr = readbackColor(ctx, graph.image(planned.hdr));
        result.depth = readbackDepth(ctx, graph.image(planned.depth));
    }
    planned.renderer->collectStats(graph);
    if (settings.debug) result.debugImages = planned.renderer->debugImages(graph);
    result.stats = planned.renderer->stats();
    // The measure of the MSAA shading rate: --msaa-shading pixel runs about one invocation per
    // covered pixel and primitive, sample about one per covered sample.
    const std::vector<PassCounts> counts = statistics ? statistics->read() : std::vector<PassCounts>{};
    noteStatistics(result, statistics);
    if (result.statisticsCollected) {
        uint64_t n = 0;
        for (const PassCounts& c : counts)
            n += c.counts.fragmentInvocations;
        result.stats.counters.push_back({"fragment_shader_invocations", double(n)});
        result.stats.counters.push_back({"fragment_invocations_per_pixel",
                                         double(n) / double(settings.width * settings.height)});
    }
    result.memory = ctx.ledger.entriesOf(entry.name);
    result.passes = graph.livePasses();
    result.culledPasses = graph.culledPasses();
    result.work = countWork(graph, counts, result);
    if (options.ceilings && result.statisticsCollected)
        result.efficiency = placeFrame(result.work, result.timings, *options.ceilings,
                                       spotShare(scene.scene().lights));
    return result;
}

} // namespace detail

void planSceneShadows(GpuContext& ctx, SceneGpu& scene, const ShadowSettings& settings) {
    scene.setShadows(settings, planShadows(scene, settings, ctx.caps.maxImageDimension2D));
}

Result<PlannedRenderer> planRenderer(GpuContext& ctx, SceneGpu& scene, const RendererEntry& entry,
                                     const SceneFeatures& features,
                                     const RenderSettings& settings) {
    // The count alone, without the pipeline's name: the CLI's line (checkSampleCount).
    if (Status s = checkSampleCount(ctx, settings.msaa); !s) return Error{s.error()};
    scene.setView(settings.width, settings.height, settings.msaa);
    planSceneShadows(ctx, scene, settings.shadows);
    PlannedRenderer planned;
    planned.graph = std::make_unique<FrameGraph>(ctx, entry.name, settings.width, settings.height);
    FrameGraph& graph = *planned.graph;
    bool exports = true;
    Status built = detail::pipelineStep(entry, [&] {
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
    Result<std::unique_ptr<RendererSession>> session =
        RendererSession::create(ctx, scene, entry, features, settings);
    if (!session) return Error{session.error()};
    return (*session)->render(options);
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

double frameMedianMs(const RunResult& run) {
    for (const TimingStats& t : run.timings)
        if (t.name == "frame") return t.medianMs;
    return 0.0;
}

double counterValue(const RunResult& run, const std::string& name, double fallback) {
    return run.stats.counter(name, fallback);
}

} // namespace tp
