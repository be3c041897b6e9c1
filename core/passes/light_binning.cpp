#include "core/passes/light_binning.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <functional>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/readback.h"
#include "core/gpu/vk_check.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/lightassign/compact_layout.h"
#include "core/lightassign/tile_bound.h"
#include "core/renderer/renderer.h"
#include "include/light_binning.h"

namespace tp::la {
namespace {

enum Step { kClear, kRects, kRows, kColumns, kWords, kFill, kSort, kSortStep, kSortLocal, kSteps };
const char* const kShaders[kSteps] = {
    "la_bin_clear_comp",        "la_bin_rects_comp",      "la_bin_scan_rows_comp",
    "la_bin_scan_columns_comp", "la_bin_scan_words_comp", "la_bin_fill_comp",
    "la_bin_sort_comp",         "la_bin_sort_step_comp",  "la_bin_sort_local_comp"};

// Between the steps of the pass: each reads what the one before wrote (hand-written: the
// graph orders passes, not the dispatches within one).
void stepBarrier(VkCommandBuffer cmd) {
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

} // namespace

GpuBinning::GpuBinning(GpuContext& ctx, SceneGpu& scene, const TileGrid& grid,
                       const std::vector<uint32_t>& local, std::string owner, bool manyViews,
                       const BinningTuning& tuning)
    : ctx_(ctx), scene_(scene), grid_(grid), locals_(uint32_t(local.size())),
      owner_(std::move(owner)), manyViews_(manyViews) {
    static_assert(kSortBuckets == TP_BIN_SORT_BUCKETS && kSharedSortWords == TP_BIN_SHARED_SORT);
    const uint32_t sortBuckets = tuning.sortBuckets;
    // bin_sort.comp's buckets: a power of two (a shift), at most 1,024 (shared memory).
    if (sortBuckets < 2 || sortBuckets > 1024 || (sortBuckets & (sortBuckets - 1)) != 0)
        throw std::logic_error("GpuBinning: the sort's buckets must be a power of two, 2 to 1,024");
    // The sort's buckets span local.front() to local.back(): every run's light lies between.
    if (std::adjacent_find(local.begin(), local.end(), std::greater_equal<uint32_t>()) != local.end())
        throw std::logic_error("GpuBinning: the local lights must be ascending");
    // Its largest buffer: the light list, bound whole.
    if (uint64_t(local.size()) * 4 > ctx_.caps.maxStorageBufferRange)
        throw RendererError("--light-bin gpu: a list of " + std::to_string(local.size()) +
                            " point/spot lights needs more than maxStorageBufferRange (" +
                            std::to_string(ctx_.caps.maxStorageBufferRange) + ") of " +
                            ctx_.info.name + "; use --light-bin cpu or fewer lights");
    // The lights to bin, once per configuration; the grid and its slab planes (the CPU's floats)
    // per view (uploadInputs).
    uploadInputs();
    std::vector<uint32_t> list = local.empty() ? std::vector<uint32_t>{0} : local;
    localList_ = createBufferWithData(
        ctx_, list.data(), list.size() * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
        {owner_, "light_binning", "light_bin_lights", "GPU binning: point/spot lights"});
    std::vector<SetBinding> bindings;
    for (uint32_t b = TP_BIN_BINDING_INPUTS; b <= TP_BIN_BINDING_WORDS; ++b)
        bindings.push_back({b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    set_ = createPassSet(ctx_, bindings);
    set_.pass = "light_binning";
    set_.bindings = bindings;
    layout_ = scene_.createPipelineLayout(set_.layout);
    std::vector<SpecConstant> spec = scene_.specConstants(AlphaMode::Opaque);
    // Vulkan guarantees only 128 invocations per workgroup: a GPU that allows fewer than 256 gets
    // its limit, rounded down to a power of two (bin_sort.comp scans its lanes in groups of 16).
    const VkPhysicalDeviceLimits& limits = ctx_.properties.limits;
    const uint32_t sortGroup =
        ctx_.isCpuDevice()
            ? TP_BIN_SORT_GROUP_CPU
            : std::bit_floor(std::min({TP_BIN_SORT_GROUP_GPU, limits.maxComputeWorkGroupInvocations,
                                       limits.maxComputeWorkGroupSize[0]}));
    spec.push_back({TP_BIN_SPEC_SORT_GROUP, sortGroup});
    spec.push_back({TP_BIN_SPEC_SORT_BUCKETS, sortBuckets});
    const bool manyPerTile = uint64_t(locals_) >= uint64_t(TP_BIN_FILL_RESERVE_PER_TILE) * grid_.count();
    fillReserve_ = tuning.fillReserve.value_or(!ctx_.isCpuDevice() && manyPerTile);
    spec.push_back({TP_BIN_SPEC_FILL_RESERVE, fillReserve_ ? TP_BIN_FILL_RESERVE_WORDS : 1u});
    spec.push_back({TP_BIN_SPEC_SORT_SHARED, sharedRun_});
    spec_ = spec;
    try {
        for (int step = 0; step < kSteps; ++step) // the sort's at the first sizing (sizeSortRun)
            pipelines_.push_back(step == kSort ? VK_NULL_HANDLE
                                               : createComputePipeline(ctx_, kShaders[step], spec,
                                                                       layout_, &set_));
    } catch (...) {
        destroyPipelines(); // no destructor runs for an object whose constructor throws
        throw;
    }
}

// The grid and the slab planes of the uploaded projection: made at the first call, overwritten
// in place when a new view's projection moves the planes.
void GpuBinning::uploadInputs() {
    const std::vector<glm::vec4> slabs = binSlabPlanes(grid_, scene_.shadingFrame().proj);
    gpu::BinInputs in{};
    const uint32_t X = grid_.tilesX, Y = grid_.tilesY;
    in.grid = glm::uvec4(X, Y, grid_.count(), locals_);
    in.slabs = glm::uvec4(0, X, 2 * X, 2 * X + Y);
    std::vector<uint8_t> bytes(sizeof(in) + slabs.size() * sizeof(glm::vec4));
    std::memcpy(bytes.data(), &in, sizeof(in));
    std::memcpy(bytes.data() + sizeof(in), slabs.data(), slabs.size() * sizeof(glm::vec4));
    if (!inputs_.buffer)
        inputs_ = createBufferWithData(
            ctx_, bytes.data(), bytes.size(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
            {owner_, "light_binning", "light_bin_inputs", "GPU binning: tile grid, slab planes"});
    else if (bytes != inputBytes_)
        uploadBufferData(ctx_, inputs_, bytes.data(), bytes.size());
    inputBytes_ = std::move(bytes);
}

GpuBinning::~GpuBinning() {
    destroyPipelines();
}

void GpuBinning::destroyPipelines() {
    for (VkPipeline p : pipelines_)
        vkDestroyPipeline(ctx_.device, p, nullptr);
    pipelines_.clear();
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    layout_ = VK_NULL_HANDLE;
    destroyPassSet(ctx_, set_);
}

void GpuBinning::bind(const Bufs& b, VkBuffer target) {
    writeBufferDescriptor(ctx_, set_.set, TP_BIN_BINDING_INPUTS, inputs_.buffer);
    writeBufferDescriptor(ctx_, set_.set, TP_BIN_BINDING_LOCALS, localList_.buffer);
    writeBufferDescriptor(ctx_, set_.set, TP_BIN_BINDING_COUNTS, b.counts);
    writeBufferDescriptor(ctx_, set_.set, TP_BIN_BINDING_OFFSETS, b.offsets);
    writeBufferDescriptor(ctx_, set_.set, TP_BIN_BINDING_ROWS, b.rows);
    writeBufferDescriptor(ctx_, set_.set, TP_BIN_BINDING_TARGET, target);
    writeBufferDescriptor(ctx_, set_.set, TP_BIN_BINDING_RECTS, b.rects);
    // The word layout's buffer, or a stand-in the scan never runs on.
    writeBufferDescriptor(ctx_, set_.set, TP_BIN_BINDING_WORDS,
                          words_.buffer && b.rows == frame_.rows ? words_.buffer : b.rows);
}

void GpuBinning::publishWords(VkBuffer out, uint32_t scale, uint32_t add, uint64_t room,
                              uint64_t firstWord, bool indices) {
    if (firstWord + grid_.count() > 0xffffffffull)
        throw std::logic_error("GpuBinning: the word layout's first word exceeds 32 bits");
    if (scale & TP_BIN_WORDS_INDICES)
        throw std::logic_error("GpuBinning: the word layout's scale exceeds 31 bits");
    words_ = {out, scale | (indices ? TP_BIN_WORDS_INDICES : 0u), add,
              uint32_t(std::min<uint64_t>(room, 0xffffffffull)), uint32_t(firstWord)};
    if (target_) bind(frame_, target_);
}

LightBins GpuBinning::sizes() {
    uploadInputs();
    // Sizing buffers, freed on return; the frame's live in its graph.
    const VkBufferUsageFlags usage =
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    auto make = [&](uint64_t words, const char* name) {
        return createBuffer(
            ctx_, std::max<uint64_t>(words, 4) * 4, usage, MemoryKind::Device,
            {owner_, "light_binning", name, "GPU binning at plan time (freed before the frame)"});
    };
    const uint32_t tiles = grid_.count();
    Buffer counts = make(2 * uint64_t(tiles), "light_bin_sizing_counts"),
           offsets = make(tiles + 1 + TP_BIN_NEEDS, "light_bin_sizing_offsets"),
           rows = make(grid_.tilesY, "light_bin_sizing_rows");
    bind({counts.buffer, offsets.buffer, rows.buffer, rows.buffer},
         rows.buffer); // target and rectangles: unused here
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
        begin(cmd);
        recordSizing(cmd, false); // rectangles counted, not stored
        // readbackBuffer copies in a later submission.
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                      VK_ACCESS_2_TRANSFER_READ_BIT);
    });
    auto words = [&](const Buffer& b, uint32_t n) {
        std::vector<uint8_t> bytes = readbackBuffer(ctx_, b);
        std::vector<uint32_t> w(n);
        std::memcpy(w.data(), bytes.data(), size_t(n) * 4);
        return w;
    };
    LightBins bins;
    bins.bound = words(counts, tiles);
    bins.offsets = words(offsets, tiles + 1);
    // The unclamped total (and the layout callers refuse) from the counts, as on the CPU.
    bins.slots = makeCompactLayout(bins.bound).slots;
    if (!bins.bound.empty())
        bins.maxBound = *std::max_element(bins.bound.begin(), bins.bound.end());
    if (sizingRuns_++ == 0) { // the frame's longest run: planned once, checked after each view
        runBound_ = manyViews_ ? std::min(locals_, std::max(1u, bins.maxBound) * kRunHeadroom)
                               : bins.maxBound;
        sizeSortRun();
    }
    if (target_) bind(frame_, target_); // a later view's sizing: the frame's buffers again
    return bins;
}

// bin_sort.comp's run in shared memory sized to the planned longest run
// (include/light_binning.h: TP_BIN_SPEC_SORT_SHARED): its pipeline is made here, at the first
// sizing, before any frame is recorded.
void GpuBinning::sizeSortRun() {
    sharedRun_ = std::clamp(std::bit_ceil(runBound_), TP_BIN_SORT_SHARED_LEAST, TP_BIN_SHARED_SORT);
    for (SpecConstant& c : spec_)
        if (c.id == TP_BIN_SPEC_SORT_SHARED) c.value = sharedRun_;
    pipelines_[kSort] = createComputePipeline(ctx_, kShaders[kSort], spec_, layout_, &set_);
}

bool GpuBinning::overflowed(FrameGraph& graph, uint32_t batch, uint32_t extra) {
    const std::vector<uint8_t> bytes = graph.watched(offsets_); // copied at the frame's end
    uint32_t need[TP_BIN_NEEDS];
    if (bytes.size() != sizeof(need)) return false; // no frame has run
    std::memcpy(need, bytes.data(), sizeof(need));
    const uint32_t run = need[TP_BIN_NEED_RUN];
    // A longer run than planned matters only where the recording would differ: the long-run
    // sort's steps (runs past shared memory, up to std::bit_ceil(runBound)) and the consumer's
    // batches. So a single view's exact bound is not outgrown by a view one light longer.
    const auto sorted = [](uint32_t n) { return n <= TP_BIN_SHARED_SORT ? 0u : std::bit_ceil(n); };
    const auto batches = [&](uint64_t n) { return (extra + n + batch - 1) / std::max(batch, 1u); };
    // A run past the sort's shared run, which only the block sort (past TP_BIN_SHARED_SORT)
    // would sort, is longer too.
    const bool pastShared = run > sharedRun_ && sharedRun_ < TP_BIN_SHARED_SORT;
    const bool longer = pastShared || sorted(run) > sorted(runBound_) || batches(run) > batches(runBound_);
    return need[TP_BIN_NEED_SLOTS] > room_ || longer ||
           (words_.buffer && need[TP_BIN_NEED_WORDS] > words_.room);
}

LightBins GpuBinning::collect(FrameGraph& graph) {
    const uint32_t tiles = grid_.count();
    const std::vector<uint8_t> bytes = readbackBuffer(ctx_, graph.buffer(offsets_));
    LightBins bins;
    bins.offsets.resize(size_t(tiles) + 1);
    std::memcpy(bins.offsets.data(), bytes.data(), bins.offsets.size() * 4);
    bins.bound.resize(tiles);
    for (uint32_t t = 0; t < tiles; ++t) {
        bins.bound[t] = bins.offsets[t + 1] - bins.offsets[t];
        bins.maxBound = std::max(bins.maxBound, bins.bound[t]);
    }
    bins.slots = bins.offsets[tiles];
    std::memcpy(&sortFallbacks_, bytes.data() + (size_t(tiles) + 1 + TP_BIN_NEED_FALLBACKS) * 4, 4);
    cornerAtomics_ = countCornerAtomics(readbackBuffer(ctx_, graph.buffer(rects_)));
    return bins;
}

void GpuBinning::plan(FrameGraph& graph) {
    const uint32_t tiles = grid_.count();
    counts_ = graph.createBuffer("light_bin_counts", uint64_t(tiles) * 8,
                                 "GPU binning: lights covering each tile (corners, direct)");
    offsets_ = graph.createBuffer("light_bin_offsets", (uint64_t(tiles) + 1 + TP_BIN_NEEDS) * 4,
                                  "GPU binning: each tile's first candidate (prefix sum), the "
                                  "view's needs");
    rows_ = graph.createBuffer("light_bin_rows", uint64_t(grid_.tilesY) * 4,
                               "GPU binning: per row, its scans' sum");
    rects_ = graph.createBuffer("light_bin_rects", uint64_t(std::max(locals_, 1u)) * 8,
                                "GPU binning: each light's tile rectangle, for the fill");
    // Three timed passes, so the sweep reports each part: the counts and offsets, the fill,
    // the sort. Their runs go to a buffer outside the graph (ordered by hand-written barriers).
    graph.addPass("light_binning",
                  {{counts_, Use::StorageWrite},
                   {offsets_, Use::StorageWrite},
                   {rows_, Use::StorageWrite},
                   {rects_, Use::StorageWrite}},
                  [this](PassContext& pc) {
                      begin(pc.cmd);
                      recordSizing(pc.cmd, true);
                  });
    graph.addPass(
        "light_bin_fill",
        {{counts_, Use::StorageWrite}, {offsets_, Use::StorageRead}, {rects_, Use::StorageRead}},
        [this](PassContext& pc) {
            begin(pc.cmd);
            recordFill(pc.cmd);
        });
    // The sort touches no count (the fill counted them down); it declares them written so that
    // the graph keeps the fill and the sort live (a pass lives when it writes something needed)
    // and orders it after the fill.
    graph.addPass("light_bin_sort", {{offsets_, Use::StorageRead}, {counts_, Use::StorageWrite}},
                  [this](PassContext& pc) {
                      begin(pc.cmd);
                      recordSort(pc.cmd);
                  });
    // Read after the frame by the tests; also what keeps the passes live.
    graph.exportResource("light_bin_offsets", offsets_);
    graph.exportResource("light_bin_counts", counts_);
    graph.exportResource("light_bin_rects", rects_); // collect() counts the corners' atomics
    // The view's needs, which overflowed() reads after every view's frames.
    graph.watchAfterFrame(offsets_, (uint64_t(tiles) + 1) * 4, TP_BIN_NEEDS * 4);
}

void GpuBinning::prepare(FrameGraph& graph, VkBuffer target, uint64_t baseWord,
                         uint64_t offsetsWord, uint64_t room) {
    if (baseWord > 0xffffffffull || offsetsWord + grid_.count() > 0xffffffffull)
        throw std::logic_error("GpuBinning: the target's first word exceeds 32 bits");
    base_ = uint32_t(baseWord);
    offsetsWord_ = uint32_t(offsetsWord);
    room_ = uint32_t(std::min<uint64_t>(room, 0xffffffffull));
    frame_ = {graph.buffer(counts_).buffer, graph.buffer(offsets_).buffer,
              graph.buffer(rows_).buffer, graph.buffer(rects_).buffer};
    target_ = target;
    bind(frame_, target_);
}

void GpuBinning::begin(VkCommandBuffer cmd) {
    scene_.bindSceneSet(cmd, layout_, VK_PIPELINE_BIND_POINT_COMPUTE);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, TP_SET_PASS, 1, &set_.set,
                            0, nullptr);
}

// 64 invocations per workgroup over `count` items.
void GpuBinning::dispatchFlat(VkCommandBuffer cmd, VkPipeline pipeline, uint32_t count,
                              const gpu::DrawPush& push) {
    dispatchGroups(cmd, pipeline, (count + 63) / 64, push);
}

// `groups` workgroups, in rows of at most 65,535 (a dispatch dimension's limit).
void GpuBinning::dispatchGroups(VkCommandBuffer cmd, VkPipeline pipeline, uint32_t groups,
                                const gpu::DrawPush& push) {
    if (groups == 0) return;
    const uint32_t x = std::min(groups, 65535u), y = (groups + x - 1) / x;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
    vkCmdDispatch(cmd, x, y, 1);
}

// Steps 1-4: counts and offsets; the frame (`frame`) also stores the rectangles for the fill
// and publishes the offsets, clamped to the room, into the target.
void GpuBinning::recordSizing(VkCommandBuffer cmd, bool frame) {
    if (frame) // the previous frame's culling and shading read the published offsets (WAR), and
               // the target was uploaded outside the graph (WAW)
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                      VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    const gpu::DrawPush push{0, base_, 0, 0};
    dispatchFlat(cmd, pipelines_[kClear], 2 * grid_.count(), push); // corners, direct counts
    stepBarrier(cmd);
    dispatchFlat(cmd, pipelines_[kRects], locals_, {frame ? 1u : 0u, base_, 0, 0});
    stepBarrier(cmd);
    // A workgroup per row, then per column (bin_scan_columns.comp: counts and offsets).
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_[kRows]);
    vkCmdDispatch(cmd, grid_.tilesY, 1, 1);
    stepBarrier(cmd);
    const gpu::DrawPush columns =
        frame ? gpu::DrawPush{1u, base_, offsetsWord_, room_} : gpu::DrawPush{0u, base_, 0u, ~0u};
    dispatchGroups(cmd, pipelines_[kColumns], grid_.tilesX, columns);
    if (frame && words_.buffer) { // the consumer's word layout over the counts
        stepBarrier(cmd);
        dispatchGroups(cmd, pipelines_[kWords], 1,
                       {words_.scale, words_.add, words_.room, words_.first});
    }
    if (frame) // the published offsets: read by the culling and shading (any stage)
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                      VK_ACCESS_2_MEMORY_READ_BIT);
}

// Step 5: the runs, unsorted, into the target (pass light_bin_fill).
void GpuBinning::recordFill(VkCommandBuffer cmd) {
    // The previous frame's culling and shading read the target (WAR), and it was uploaded
    // before any frame: outside the graph, so ordered here.
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    const uint32_t rows = std::max(1u, TP_BIN_FILL_BUDGET / std::max(1u, grid_.tilesX));
    const uint32_t groups = (locals_ + 63) / 64;
    const uint32_t target = ctx_.isCpuDevice() ? TP_BIN_FILL_GROUPS_CPU : TP_BIN_FILL_GROUPS_GPU;
    const uint32_t split =
        groups == 0 ? 1 : std::clamp(target / groups, 1u, uint32_t(TP_BIN_FILL_SPLIT_MAX));
    for (uint32_t first = 0; first < grid_.tilesY; first += rows) {
        if (first > 0)
            stepBarrier(cmd); // the same buffers (the validation layer cannot see the rows differ)
        dispatchGroups(cmd, pipelines_[kFill], groups * split,
                       {split, base_, first, std::min(grid_.tilesY, first + rows)});
    }
}

// Step 6: every run sorted in place (pass light_bin_sort).
void GpuBinning::recordSort(VkCommandBuffer cmd) {
    if (!pipelines_[kSort]) throw std::logic_error("GpuBinning: a frame before sizes()");
    stepBarrier(cmd); // the fill's target writes (outside the graph)
    const gpu::DrawPush push{0, base_, 0, 0};
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_[kSort]);
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
    vkCmdDispatch(cmd, grid_.tilesX, grid_.tilesY, 1);
    if (runBound_ > TP_BIN_SHARED_SORT) {
        // Runs too long for shared memory: a bitonic sort over blocks of TP_BIN_SHARED_SORT.
        // Steps within a block in shared memory (bin_sort_local), one dispatch for all the
        // steps of a merge that stay in the block; a dispatch per step only for the distances
        // of a block or more (bin_sort_step): for a run of 16,384, 6 dispatches, not 105.
        const uint32_t size = std::bit_ceil(runBound_), blocks = size / TP_BIN_SHARED_SORT;
        const uint32_t chunks = (size / 2 + 64 * TP_BIN_STEP_PAIRS - 1) / (64 * TP_BIN_STEP_PAIRS);
        auto local = [&](uint32_t kFrom, uint32_t kTo) {
            stepBarrier(cmd);
            const gpu::DrawPush p{0, base_, kFrom, kTo};
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_[kSortLocal]);
            vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_ALL, 0, sizeof(p), &p);
            vkCmdDispatch(cmd, blocks, grid_.tilesX, grid_.tilesY);
        };
        local(2, TP_BIN_SHARED_SORT); // every block sorted
        for (uint32_t k = 2 * TP_BIN_SHARED_SORT; k <= size; k <<= 1) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_[kSortStep]);
            for (uint32_t j = k >> 1; j >= TP_BIN_SHARED_SORT; j >>= 1) {
                stepBarrier(cmd);
                const gpu::DrawPush step{0, base_, k, j};
                vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_ALL, 0, sizeof(step), &step);
                vkCmdDispatch(cmd, chunks, grid_.tilesX, grid_.tilesY);
            }
            local(k, k); // the merge's steps below the block
        }
    }
    // The culling (compute) and Forward+'s shading (fragment: the same buffer) read it next.
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
}

} // namespace tp::la
