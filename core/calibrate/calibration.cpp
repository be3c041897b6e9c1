#include "core/calibrate/calibration.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "core/calibrate/rig.h"
#include "core/gpu/barriers.h"
#include "core/gpu/context.h"
#include "core/gpu/profiler.h"
#include "core/gpu/vk_check.h"

namespace tp {
namespace {

using calibrate::Bench;
using calibrate::Rig;
using calibrate::Targets;

// Times `b` once and returns the GPU time in ms (its profiler keeps the sample).
double submitOnce(Rig& rig, const Bench& b, VkPipeline pipeline, const Targets& targets, GpuProfiler& profiler) {
    rig.ctx.submitAndWait([&](VkCommandBuffer cmd) {
        // The previous dispatch (or the fill) wrote the buffers: finish it first, outside the
        // timed scope. Draws write only their own targets (their barriers are inside).
        if (!b.graphics)
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                          VK_ACCESS_2_MEMORY_WRITE_BIT | VK_ACCESS_2_MEMORY_READ_BIT,
                          VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                          VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        profiler.beginFrame(cmd);
        uint32_t scope = profiler.beginScope(cmd, b.name);
        recordBench(cmd, rig, b, pipeline, targets);
        profiler.endScope(cmd, scope);
        profiler.endFrame(cmd);
    });
    profiler.collect();
    return profiler.stats().back().maxMs;
}

// A dispatch this short is mostly its launch: the warm-up's time decides how many times
// longer the timed ones loop (at most 64 times, within lavapipe's 65,535 loop iterations).
constexpr double kMinDispatchMs = 2.0;

// Times `b` over 1 + repeats submissions of one dispatch or draw: the first (the warm-up)
// sizes the others to take at least kMinDispatchMs, and is discarded.
Ceiling run(Rig& rig, Bench b, uint32_t repeats) {
    GpuContext& ctx = rig.ctx;
    VkPipeline pipeline = createBenchPipeline(rig, b);
    const Targets targets = createTargets(ctx, b);
    GpuProfiler profiler(ctx, 2);
    const double warmupMs = submitOnce(rig, b, pipeline, targets, profiler);
    profiler.discardSamples();
    const uint32_t scale =
        b.scalable ? uint32_t(std::clamp(std::ceil(kMinDispatchMs / std::max(warmupMs, 1e-6)), 1.0, 64.0)) : 1u;
    b.push.iterations *= scale;
    b.work *= scale;
    for (uint32_t r = 0; r < repeats; ++r)
        submitOnce(rig, b, pipeline, targets, profiler);
    vkDestroyPipeline(ctx.device, pipeline, nullptr);
    const TimingStats t = profiler.stats().back();
    // Every unit is a billion of the work's base unit per second.
    auto rate = [&](double ms) { return ms > 0 ? b.work / (ms * 1e-3) / 1e9 : 0.0; };
    return {b.name, b.unit, b.what, rate(t.medianMs), rate(t.maxMs), rate(t.minMs), t.medianMs, b.work,
            t.frames};
}

// The streams' buffer size: far larger than any last-level cache (the H100's L2 is 50 MB),
// and on a GPU large enough that one pass takes long beside a dispatch's launch (1 GiB: 0.37 ms
// on an H100); within one binding's range and an eighth of the largest device-local heap (two
// buffers); a power of two (the index mask is its length in vec4 minus one).
uint64_t streamBytes(const GpuContext& ctx, bool quick) {
    uint64_t heap = 0;
    for (uint32_t i = 0; i < ctx.memoryProperties.memoryHeapCount; ++i)
        if (ctx.memoryProperties.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            heap = std::max<uint64_t>(heap, ctx.memoryProperties.memoryHeaps[i].size);
    const uint64_t wanted = quick ? (16ull << 20) : ctx.isCpuDevice() ? (256ull << 20) : (1ull << 30);
    return std::bit_floor(std::min({wanted, uint64_t(ctx.caps.maxStorageBufferRange), std::max<uint64_t>(heap / 8, 16ull << 20)}));
}

} // namespace

std::vector<std::string> ceilingNames() {
    std::vector<std::string> out;
    for (const Bench& b : calibrate::benches(1 << 20, true))
        out.push_back(b.name);
    return out;
}

std::vector<Ceiling> measureCeilings(GpuContext& ctx, const CalibrationOptions& options) {
    if (options.repeats == 0) throw std::invalid_argument("calibrate: --repeats must be at least 1");
    const uint64_t bytes = streamBytes(ctx, options.quick);
    Rig rig(ctx, bytes);
    std::vector<Ceiling> out;
    const std::vector<Bench> all = calibrate::benches(bytes, options.quick);
    for (size_t i = 0; i < all.size(); ++i) {
        if (options.progress)
            options.progress("[" + std::to_string(i + 1) + "/" + std::to_string(all.size()) + "] " + all[i].name + " ...");
        out.push_back(run(rig, all[i], options.repeats));
    }
    return out;
}

} // namespace tp
