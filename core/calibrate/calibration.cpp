#include "core/calibrate/calibration.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "calibrate/calibrate_shared.h"
#include "core/gpu/barriers.h"
#include "core/gpu/context.h"
#include "core/gpu/descriptors.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/profiler.h"
#include "core/gpu/resources.h"
#include "core/gpu/vk_check.h"

namespace tp {
namespace {

using gpu::CalPush;

// One microbenchmark: its shader kind, its dispatch, and how much work one dispatch does.
struct Bench {
    const char* name;
    uint32_t kind; // TP_CAL_*
    const char* unit;
    const char* what;
    uint32_t invocations = 0; // compute: a multiple of TP_CAL_GROUP_SIZE; fragment: pixels
    CalPush push{};
    double work = 0; // in the unit's base (bytes, FLOPs, atomics)
};

constexpr double kVec4Bytes = 16.0;
constexpr VkFormat kTargetFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkShaderStageFlags kPushStages = VK_SHADER_STAGE_COMPUTE_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

// The fragment ceiling's square render target: one fragment per pixel.
uint32_t targetSize(bool quick) { return quick ? 128u : 1024u; }

// The benchmarks at one size: `bufferBytes` for the streaming ones (far larger than a last-
// level cache unless quick), a 1 MiB window for the cache-resident read.
std::vector<Bench> benches(uint64_t bufferBytes, bool quick) {
    const uint32_t elements = uint32_t(bufferBytes / 16), streamSteps = quick ? 4u : 16u;
    const uint32_t streamInvocations = elements / streamSteps;
    const uint32_t aluInvocations = quick ? 16384u : 262144u;
    const uint32_t cacheWindow = std::min<uint32_t>(65536u, elements); // vec4: 1 MiB
    std::vector<Bench> b = {
        {"dram_read", TP_CAL_READ, "GB/s", "a buffer far larger than any cache, read in order (passing over it again if longer)"},
        {"dram_write", TP_CAL_WRITE, "GB/s", "the same buffer written in order"},
        {"dram_copy", TP_CAL_COPY, "GB/s", "the buffer copied to another (bytes read + written)"},
        {"cache_read", TP_CAL_CACHE_READ, "GB/s", "the same 1 MiB read over and over, a new cache line each step"},
        {"fp32_fma", TP_CAL_FMA, "GFLOP/s", "8 independent vec4 FMA chains (2 FLOPs per FMA)"},
        {"shared_atomic", TP_CAL_SHARED_ATOMIC, "Gatomic/s", "atomicAdd to shared memory, 256 words per workgroup"},
        {"global_atomic", TP_CAL_GLOBAL_ATOMIC, "Gatomic/s", "atomicAdd to 4 MiB of device memory, spread"},
        {"fragment_fma", TP_CAL_FRAGMENT_FMA, "GFLOP/s", "fp32_fma's loop per pixel of a full-screen triangle"},
    };
    for (Bench& x : b) {
        switch (x.kind) {
        case TP_CAL_READ:
        case TP_CAL_WRITE:
        case TP_CAL_COPY:
            x.invocations = streamInvocations;
            x.push = {streamInvocations, streamSteps, elements - 1u, 0u};
            x.work = double(x.invocations) * streamSteps * kVec4Bytes * (x.kind == TP_CAL_COPY ? 2 : 1);
            break;
        case TP_CAL_CACHE_READ:
            x.invocations = aluInvocations;
            // Each step 16 KiB further on in the window (wrapping): a new cache line every
            // step, never the same address twice in a row (a compiler could keep that in a
            // register), neighbouring invocations on neighbouring vec4.
            x.push = {1024u, quick ? 16u : 64u, cacheWindow - 1u, 0u};
            x.work = double(x.invocations) * x.push.iterations * kVec4Bytes;
            break;
        case TP_CAL_FMA:
            x.invocations = aluInvocations;
            x.push = {aluInvocations, quick ? 64u : 1024u, 0u, 0u};
            x.work = double(x.invocations) * x.push.iterations * 8 * 4 * 2;
            break;
        case TP_CAL_SHARED_ATOMIC:
            x.invocations = aluInvocations;
            x.push = {aluInvocations, quick ? 32u : 256u, 0u, 0u};
            x.work = double(x.invocations) * x.push.iterations;
            break;
        case TP_CAL_GLOBAL_ATOMIC:
            x.invocations = aluInvocations;
            x.push = {aluInvocations, quick ? 16u : 64u, (1u << 20) - 1u, 0u};
            x.work = double(x.invocations) * x.push.iterations;
            break;
        case TP_CAL_FRAGMENT_FMA:
            x.invocations = targetSize(quick) * targetSize(quick);
            x.push = {0u, quick ? 16u : 256u, 0u, 0u};
            x.work = double(x.invocations) * x.push.iterations * 8 * 4 * 2;
            break;
        }
    }
    return b;
}

// The buffers, descriptor set and pipeline layout every benchmark shares.
struct Rig {
    GpuContext& ctx;
    Buffer src, dst;
    PassSet set;
    VkDescriptorSetLayout emptySet = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;

    Image target; // the fragment ceiling's colour attachment

    Rig(GpuContext& c, uint64_t bytes, uint32_t targetSize) : ctx(c) {
        const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        src = createBuffer(ctx, bytes, usage, MemoryKind::Device,
                           {"calibrate", "calibrate", "source", "what the reads read (zeros)"});
        dst = createBuffer(ctx, bytes, usage, MemoryKind::Device,
                           {"calibrate", "calibrate", "destination", "what the writes and atomics write"});
        const std::vector<SetBinding> bindings = {{TP_CAL_BINDING_SRC, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                                  {TP_CAL_BINDING_DST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
        set = createPassSet(ctx, bindings);
        set.pass = "calibrate";
        set.bindings = bindings; // what reflection checks each kind's shader against
        writeBufferDescriptor(ctx, set.set, TP_CAL_BINDING_SRC, src.buffer);
        writeBufferDescriptor(ctx, set.set, TP_CAL_BINDING_DST, dst.buffer);
        VkDescriptorSetLayoutCreateInfo empty{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        VK_CHECK(vkCreateDescriptorSetLayout(ctx.device, &empty, nullptr, &emptySet));
        const VkDescriptorSetLayout sets[] = {emptySet, set.layout}; // set 1: TP_SET_PASS
        VkPushConstantRange range{kPushStages, 0, sizeof(CalPush)};
        VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        info.setLayoutCount = 2;
        info.pSetLayouts = sets;
        info.pushConstantRangeCount = 1;
        info.pPushConstantRanges = &range;
        VK_CHECK(vkCreatePipelineLayout(ctx.device, &info, nullptr, &layout));
        target = createImage(ctx, {kTargetFormat, targetSize, targetSize, 1, VK_SAMPLE_COUNT_1_BIT,
                                   VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT},
                             {"calibrate", "calibrate", "target", "the fragment ceiling's colour attachment"});
        // Zeros in both: what the reads sum, so no result is ever written back.
        ctx.submitAndWait([&](VkCommandBuffer cmd) {
            vkCmdFillBuffer(cmd, src.buffer, 0, VK_WHOLE_SIZE, 0u);
            vkCmdFillBuffer(cmd, dst.buffer, 0, VK_WHOLE_SIZE, 0u);
        });
    }
    ~Rig() {
        vkDestroyPipelineLayout(ctx.device, layout, nullptr);
        vkDestroyDescriptorSetLayout(ctx.device, emptySet, nullptr);
        destroyPassSet(ctx, set);
    }
};

VkPipeline createPipeline(Rig& rig, const Bench& b) {
    if (b.kind != TP_CAL_FRAGMENT_FMA)
        return createComputePipeline(rig.ctx, "calibrate_" + std::to_string(b.kind) + "_comp", {},
                                     rig.layout, &rig.set);
    GraphicsPipelineDesc d;
    d.vertexShader = "deferred_fullscreen_vert";
    d.fragmentShader = "calibrate_fma_frag";
    d.colorFormats = {kTargetFormat};
    d.depthFormat = VK_FORMAT_UNDEFINED;
    d.depthTest = d.depthWrite = false;
    d.layout = rig.layout; // the buffers' set is in it, unused: the draw reads nothing
    return createGraphicsPipeline(rig.ctx, d);
}

// One full-screen triangle into the target, whose previous contents do not matter.
void recordFragment(VkCommandBuffer cmd, Rig& rig, const Bench& b, VkPipeline pipeline) {
    const uint32_t size = rig.target.desc.width;
    imageBarrier(cmd, rig.target.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                 VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                 VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = rig.target.view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, {size, size}};
    info.layerCount = 1;
    info.colorAttachmentCount = 1;
    info.pColorAttachments = &color;
    vkCmdBeginRendering(cmd, &info);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    setViewportAndScissor(cmd, size, size);
    vkCmdSetCullMode(cmd, VK_CULL_MODE_NONE);
    vkCmdPushConstants(cmd, rig.layout, kPushStages, 0, sizeof(CalPush), &b.push);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);
}

void recordCompute(VkCommandBuffer cmd, Rig& rig, const Bench& b, VkPipeline pipeline) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, rig.layout, 1, 1, &rig.set.set, 0,
                            nullptr);
    vkCmdPushConstants(cmd, rig.layout, kPushStages, 0, sizeof(CalPush), &b.push);
    vkCmdDispatch(cmd, b.invocations / TP_CAL_GROUP_SIZE, 1, 1);
}

// Times `b` once and returns the GPU time in ms (its profiler keeps the sample).
double submitOnce(Rig& rig, const Bench& b, VkPipeline pipeline, GpuProfiler& profiler) {
    rig.ctx.submitAndWait([&](VkCommandBuffer cmd) {
        // The previous dispatch (or the fill) wrote the buffers: finish it first, outside the
        // timed scope.
        if (b.kind != TP_CAL_FRAGMENT_FMA)
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                          VK_ACCESS_2_MEMORY_WRITE_BIT | VK_ACCESS_2_MEMORY_READ_BIT,
                          VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                          VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        profiler.beginFrame(cmd);
        uint32_t scope = profiler.beginScope(cmd, b.name);
        if (b.kind == TP_CAL_FRAGMENT_FMA) recordFragment(cmd, rig, b, pipeline);
        else recordCompute(cmd, rig, b, pipeline);
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
    VkPipeline pipeline = createPipeline(rig, b);
    GpuProfiler profiler(ctx, 2);
    const double warmupMs = submitOnce(rig, b, pipeline, profiler);
    profiler.discardSamples();
    // Not the streams: a longer loop would pass over what the same invocation just read, from
    // a cache. Their buffer is sized instead (streamBytes).
    const bool stream = b.kind == TP_CAL_READ || b.kind == TP_CAL_WRITE || b.kind == TP_CAL_COPY;
    const uint32_t scale =
        stream ? 1u : uint32_t(std::clamp(std::ceil(kMinDispatchMs / std::max(warmupMs, 1e-6)), 1.0, 64.0));
    b.push.iterations *= scale;
    b.work *= scale;
    for (uint32_t r = 0; r < repeats; ++r)
        submitOnce(rig, b, pipeline, profiler);
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
    for (const Bench& b : benches(1 << 20, true))
        out.push_back(b.name);
    return out;
}

std::vector<Ceiling> measureCeilings(GpuContext& ctx, const CalibrationOptions& options) {
    if (options.repeats == 0) throw std::invalid_argument("calibrate: --repeats must be at least 1");
    // Far beyond any last-level cache (the H100's L2 is 50 MB), within one binding's range.
    const uint64_t bytes = streamBytes(ctx, options.quick);
    Rig rig(ctx, bytes, targetSize(options.quick));
    std::vector<Ceiling> out;
    const std::vector<Bench> all = benches(bytes, options.quick);
    for (size_t i = 0; i < all.size(); ++i) {
        if (options.progress)
            options.progress("[" + std::to_string(i + 1) + "/" + std::to_string(all.size()) + "] " +
                             all[i].name + " ...");
        out.push_back(run(rig, all[i], options.repeats));
    }
    return out;
}

} // namespace tp
