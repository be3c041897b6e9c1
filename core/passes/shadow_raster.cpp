#include "core/passes/shadow_raster.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/gpu/barriers.h"
#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/readback.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/raster_triangle_constants.h"
#include "core/passes/shadow_cull.h"
#include "core/renderer/renderer.h"

namespace tp {
namespace {
constexpr const char* kOwnPass = "shadow_maps (once)";
// Compute: groups {0, 1, 1} until shadow_raster lists a triangle.
constexpr uint32_t kArgs[4] = {0, 1, 1, 0};
} // namespace

ShadowComputeRaster::ShadowComputeRaster(GpuContext& ctx, SceneGpu& scene, const ShadowCull& cull)
    : ctx_(ctx), scene_(scene), cull_(cull) {
    // The edge functions are int64 (include/raster_triangle.glsl); the context enables
    // shaderInt64 with the 64-bit atomics.
    if (!ctx_.caps.int64Atomics)
        throw RendererError("--shadow-raster compute: " + ctx_.info.name +
                            " lacks shaderInt64; use --shadow-raster hardware");
}

ShadowComputeRaster::~ShadowComputeRaster() {
    for (VkPipeline p : {pipeline_, big_})
        if (p) vkDestroyPipeline(ctx_.device, p, nullptr);
    for (VkPipelineLayout l : {layout_, bigLayout_})
        if (l) vkDestroyPipelineLayout(ctx_.device, l, nullptr);
    if (ownSets_) { // the graph's sets are the graph's
        destroyPassSet(ctx_, set_);
        destroyPassSet(ctx_, bigSet_);
    }
}

void ShadowComputeRaster::size(uint32_t width, uint32_t height, double rowTriangles,
                               uint32_t listCapacity) {
    width_ = width;
    height_ = height;
    const VkDeviceSize bytes = VkDeviceSize(width) * height * sizeof(uint32_t);
    if (bytes > ctx_.caps.maxStorageBufferRange)
        throw RendererError("--shadow-raster compute needs the " + std::to_string(width) + "x" +
                            std::to_string(height) + " atlas's depth (" +
                            std::to_string(bytes >> 20) + " MiB) in one storage buffer, more than " +
                            ctx_.info.name + "'s " +
                            std::to_string(ctx_.caps.maxStorageBufferRange >> 20) +
                            " MiB; use a lower --shadow-budget or --shadow-raster hardware");
    const double most = std::min<double>(std::max(rowTriangles, 1.0), kMaxListed);
    capacity_ = listCapacity ? listCapacity : uint32_t(most);
}

void ShadowComputeRaster::plan(FrameGraph& graph, ResourceHandle map) {
    inFrame_ = true;
    depth_ = graph.createBuffer("shadow_raster_depth", VkDeviceSize(width_) * height_ * 4,
                                "per atlas texel: the nearest depth's float bits, 32-bit atomic "
                                "max (--shadow-raster compute), copied into the atlas");
    list_ = graph.createBuffer("shadow_raster_list",
                               (TP_SR_LIST_HEADER + 4 * VkDeviceSize(capacity_)) * 4,
                               "counters, then per large triangle of a shadow face its vertices "
                               "and row");
    args_ = graph.createBuffer("shadow_raster_args", 16, "shadow_raster_big's dispatch");
    overflow_ = graph.createBuffer("shadow_raster_overflow", cull_.commandCapacity() * 4,
                                   "the meshlets whose large triangles overflowed the list");
    graph.addPass("shadow_raster_clear",
                  {{depth_, Use::TransferDst}, {list_, Use::TransferDst}, {args_, Use::TransferDst}},
                  [this](PassContext& pc) {
                      recordClear(pc.cmd, pc.buffer(depth_).buffer, pc.buffer(list_).buffer,
                                  pc.buffer(args_).buffer);
                  });
    graph.addPass("shadow_raster",
                  {{depth_, Use::StorageWrite, TP_SR_BINDING_DEPTH},
                   {list_, Use::StorageWrite, TP_SR_BINDING_LIST},
                   {args_, Use::StorageWrite, TP_SR_BINDING_ARGS},
                   {overflow_, Use::StorageWrite, TP_SR_BINDING_OVERFLOW},
                   {cull_.commands(), Use::StorageRead, TP_SR_BINDING_COMMANDS},
                   {cull_.counts(), Use::StorageRead, TP_SR_BINDING_COUNTS}},
                  [this](PassContext& pc) { recordRaster(pc.cmd); });
    graph.addPass("shadow_raster_big",
                  {{depth_, Use::StorageWrite, TP_SR_BINDING_DEPTH},
                   {list_, Use::StorageWrite, TP_SR_BINDING_LIST}, // its atomics' count
                   {overflow_, Use::StorageRead, TP_SR_BINDING_OVERFLOW},
                   {cull_.commands(), Use::StorageRead, TP_SR_BINDING_COMMANDS},
                   {cull_.counts(), Use::StorageRead, TP_SR_BINDING_COUNTS},
                   {args_, Use::IndirectRead}},
                  [this](PassContext& pc) { recordBig(pc.cmd, pc.buffer(args_).buffer); });
    // Named as the hardware's pass: the map is made here, and the reports read its time.
    if (map.valid())
        graph.addPass("shadow_maps", {{depth_, Use::TransferSrc}, {map, Use::TransferDst}},
                  [this, map](PassContext& pc) {
                      recordCopy(pc.cmd, pc.buffer(depth_).buffer, pc.image(map).image);
                  });
    graph.exportResource("shadow_raster_list", list_);
}

VkImageView ShadowComputeRaster::standInMap(const std::string& owner) {
    if (standIn_.view) return standIn_.view;
    standIn_ = createImage(ctx_, {VK_FORMAT_D32_SFLOAT, 1, 1, 1, VK_SAMPLE_COUNT_1_BIT,
                                  VK_IMAGE_USAGE_SAMPLED_BIT},
                           {owner, "shadow_raster", "shadow_map_unused",
                            "a 1x1 stand-in for the atlas (its texels are read from "
                            "shadow_raster_depth)"});
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
        imageBarrier(cmd, standIn_.image, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                     VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1});
    });
    return standIn_.view;
}

void ShadowComputeRaster::allocate(const std::string& owner) {
    inFrame_ = false;
    const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                     VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                     VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    ownDepth_ = createBuffer(ctx_, VkDeviceSize(width_) * height_ * 4, usage, MemoryKind::Device,
                             {owner, kOwnPass, "shadow_raster_depth",
                              "per atlas texel: the nearest depth's float bits (--shadow-raster "
                              "compute), copied into the kept atlas"});
    ownList_ = createBuffer(ctx_, (TP_SR_LIST_HEADER + 4 * VkDeviceSize(capacity_)) * 4, usage,
                            MemoryKind::Device,
                            {owner, kOwnPass, "shadow_raster_list",
                             "counters, then per large triangle of a shadow face its vertices "
                             "and row"});
    ownArgs_ = createBuffer(ctx_, 16, usage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                            MemoryKind::Device,
                            {owner, kOwnPass, "shadow_raster_args", "shadow_raster_big's dispatch"});
    owner_ = owner;
    allocateOverflow();
}

// A slot per command of the cull's rows, which grow with them (ShadowCull::setRows).
void ShadowComputeRaster::allocateOverflow() {
    overflowCapacity_ = cull_.commandCapacity();
    ownOverflow_ = createBuffer(ctx_, VkDeviceSize(overflowCapacity_) * 4,
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::Device,
                                {owner_, kOwnPass, "shadow_raster_overflow",
                                 "the meshlets whose large triangles overflowed the list"});
}

void ShadowComputeRaster::prepare(FrameGraph* graph) {
    const std::vector<ExternalBuffer> externals = {
        {TP_SR_BINDING_INDICES, scene_.meshletIndexBuffer()},
        {TP_SR_BINDING_ROWS, cull_.rowBuffer()},
        {TP_SR_BINDING_FACES, scene_.shadowFaces()}};
    if (inFrame_) {
        set_ = graph->createPassSet("shadow_raster", VK_NULL_HANDLE, externals);
        bigSet_ = graph->createPassSet("shadow_raster_big", VK_NULL_HANDLE, externals);
    } else {
        std::vector<SetBinding> all, big;
        for (uint32_t b : {TP_SR_BINDING_DEPTH, TP_SR_BINDING_LIST, TP_SR_BINDING_ARGS,
                           TP_SR_BINDING_INDICES, TP_SR_BINDING_ROWS, TP_SR_BINDING_COMMANDS,
                           TP_SR_BINDING_COUNTS, TP_SR_BINDING_FACES, TP_SR_BINDING_OVERFLOW}) {
            all.push_back({b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
            if (b != TP_SR_BINDING_ARGS) big.push_back(all.back()); // its indirect dispatch
        }
        set_ = createPassSet(ctx_, all);
        set_.pass = kOwnPass;
        set_.bindings = all; // what the shader is checked against
        bigSet_ = createPassSet(ctx_, big);
        bigSet_.pass = kOwnPass;
        bigSet_.bindings = big;
        ownSets_ = true;
        writeOwnSets();
    }
    makePipelines();
}

void ShadowComputeRaster::makePipelines() {
    std::vector<SpecConstant> spec = scene_.specConstants(AlphaMode::Mask);
    spec.push_back({TP_SR_SPEC_WIDTH, width_});
    spec.push_back({TP_SR_SPEC_LOCAL, 0u}); // the atlas's rects (one light's map: not yet)
    const std::vector<SpecConstant> triangle = rasterTriangleConstants(ctx_);
    spec.insert(spec.end(), triangle.begin(), triangle.end());
    layout_ = scene_.createPipelineLayout(set_.layout);
    pipeline_ = createComputePipeline(ctx_, "shadow_raster_comp", spec, layout_, &set_);
    bigLayout_ = scene_.createPipelineLayout(bigSet_.layout);
    big_ = createComputePipeline(ctx_, "shadow_raster_big_comp", spec, bigLayout_, &bigSet_);
}

void ShadowComputeRaster::writeOwnSets() {
    const std::pair<uint32_t, VkBuffer> all[] = {
        {TP_SR_BINDING_DEPTH, ownDepth_.buffer},       {TP_SR_BINDING_LIST, ownList_.buffer},
        {TP_SR_BINDING_ARGS, ownArgs_.buffer},         {TP_SR_BINDING_INDICES, scene_.meshletIndexBuffer()},
        {TP_SR_BINDING_ROWS, cull_.rowBuffer()},       {TP_SR_BINDING_COMMANDS, cull_.commandBuffer()},
        {TP_SR_BINDING_COUNTS, cull_.countBuffer()},   {TP_SR_BINDING_FACES, scene_.shadowFaces()},
        {TP_SR_BINDING_OVERFLOW, ownOverflow_.buffer}};
    for (const auto& [binding, buffer] : all) {
        writeBufferDescriptor(ctx_, set_.set, binding, buffer);
        if (binding != TP_SR_BINDING_ARGS) writeBufferDescriptor(ctx_, bigSet_.set, binding, buffer);
    }
}

void ShadowComputeRaster::recordClear(VkCommandBuffer cmd, VkBuffer depth, VkBuffer list,
                                      VkBuffer args) const {
    vkCmdFillBuffer(cmd, depth, 0, VK_WHOLE_SIZE, 0); // 0.0f: the hardware's clear value
    vkCmdFillBuffer(cmd, list, 0, TP_SR_LIST_HEADER * 4, 0);
    vkCmdUpdateBuffer(cmd, args, 0, sizeof(kArgs), kArgs);
}

void ShadowComputeRaster::recordRaster(VkCommandBuffer cmd) const {
    // No push constants (meshlet_cull.cpp: lavapipe's queue thread and a push before the
    // frame's first graphics pipeline); the group's command slot is its index in the grid.
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    scene_.bindSceneSet(cmd, layout_, VK_PIPELINE_BIND_POINT_COMPUTE);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    const uint32_t slots = cull_.commandCapacity();
    const uint32_t groups = std::max(1u, (slots + TP_SR_SLOTS_PER_GROUP - 1) / TP_SR_SLOTS_PER_GROUP);
    const uint32_t x = std::min(groups, 65535u);
    vkCmdDispatch(cmd, x, (groups + x - 1) / x, 1);
}

void ShadowComputeRaster::recordBig(VkCommandBuffer cmd, VkBuffer args) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, big_);
    scene_.bindSceneSet(cmd, bigLayout_, VK_PIPELINE_BIND_POINT_COMPUTE);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, bigLayout_, TP_SET_PASS, 1,
                            &bigSet_.set, 0, nullptr);
    vkCmdDispatchIndirect(cmd, args, 0);
}

void ShadowComputeRaster::recordCopy(VkCommandBuffer cmd, VkBuffer depth, VkImage image) const {
    recordDepthCopy(cmd, depth, image, width_, height_);
}

void ShadowComputeRaster::recordOwn(VkCommandBuffer cmd, VkImage image) {
    if (cull_.commandCapacity() > overflowCapacity_) allocateOverflow(); // the rows grew
    writeOwnSets();
    const VkPipelineStageFlags2 compute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    const VkPipelineStageFlags2 transfer = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
    const VkAccessFlags2 storage =
        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    // The last render's reads of the buffers (the copy, the shaders) before the clear.
    memoryBarrier(cmd, compute | transfer | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                  VK_ACCESS_2_MEMORY_READ_BIT, transfer, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    recordClear(cmd, ownDepth_.buffer, ownList_.buffer, ownArgs_.buffer);
    memoryBarrier(cmd, transfer, VK_ACCESS_2_TRANSFER_WRITE_BIT, compute, storage);
    recordRaster(cmd);
    // The depth and the list written, the big pass's dispatch counted.
    memoryBarrier(cmd, compute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  compute | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                  storage | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
    recordBig(cmd, ownArgs_.buffer);
    memoryBarrier(cmd, compute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, transfer,
                  VK_ACCESS_2_TRANSFER_READ_BIT);
    const VkImageSubresourceRange depthRange{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
    // The old maps are discarded; the frames sampled them before this submission waited.
    imageBarrier(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | compute, VK_ACCESS_2_NONE, transfer,
                 VK_ACCESS_2_TRANSFER_WRITE_BIT, depthRange);
    recordCopy(cmd, ownDepth_.buffer, image);
    imageBarrier(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, transfer, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                 VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | compute,
                 VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, depthRange);
}

void ShadowComputeRaster::collect(FrameGraph* graph) {
    // The frame's list (the graph's) or the kept atlas's own (graph may be null then).
    const std::vector<uint8_t> raw =
        inFrame_ && graph ? readbackBuffer(ctx_, graph->buffer(list_)) : readbackBuffer(ctx_, ownList_);
    std::memcpy(counts_, raw.data(), sizeof(counts_));
    collected_ = true;
}

std::vector<std::pair<std::string, double>> ShadowComputeRaster::counters() const {
    std::vector<std::pair<std::string, double>> c = {
        {"shadow_raster_list_capacity", double(capacity_)}};
    if (!collected_) return c;
    const double small = counts_[TP_SR_COUNT_SMALL], listed = counts_[TP_SR_COUNT_BIG];
    c.push_back({"shadow_raster_triangles", small + listed});
    c.push_back({"shadow_raster_triangles_small", small});
    c.push_back({"shadow_raster_triangles_listed", listed});
    c.push_back({"shadow_raster_triangles_culled", double(counts_[TP_SR_COUNT_CULLED])});
    c.push_back({"shadow_raster_triangles_clipped", double(counts_[TP_SR_COUNT_CLIPPED])});
    c.push_back({"shadow_raster_triangles_overflow", double(counts_[TP_SR_OVERFLOW])});
    c.push_back({"shadow_raster_depth_atomics",
                 double(counts_[TP_SR_ATOMICS_SMALL]) + double(counts_[TP_SR_ATOMICS_BIG])});
    return c;
}

} // namespace tp
