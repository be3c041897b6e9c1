#include "visbuffer/raster_pass.h"

#include <algorithm>
#include <cstring>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/readback.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/meshlet_cull.h"
#include "core/passes/raster_triangle_constants.h"
#include "core/renderer/renderer.h"
#include "visbuffer/vis_raster.h"

namespace tp::vis {

RasterPass::RasterPass(GpuContext& ctx, SceneGpu& scene, const DrawTable& table, bool hybrid)
    : ctx_(ctx), scene_(scene), table_(table), hybrid_(hybrid) {
    if (!ctx_.caps.int64Atomics)
        throw RendererError("visbuffer: " + ctx_.info.name +
                            " lacks shaderInt64 or shaderBufferInt64Atomics, which --vis-raster " +
                            (hybrid ? "hybrid" : "compute") + " needs; use --vis-raster hardware");
    // Hybrid: the masked draws stay with the hardware (their alpha test, per sample).
    draws_ = table_.opaque;
    if (!hybrid_) draws_.insert(draws_.end(), table_.masked.begin(), table_.masked.end());
    for (const TableDraw& t : draws_)
        triangles_ += t.item->indexCount / 3;
}

RasterPass::~RasterPass() {
    for (VkPipeline p : {pipeline_, big_, order_})
        if (p) vkDestroyPipeline(ctx_.device, p, nullptr);
    for (VkPipelineLayout l : {layout_, bigLayout_, orderLayout_})
        if (l) vkDestroyPipelineLayout(ctx_.device, l, nullptr);
    destroyPassSet(ctx_, set_);
    destroyPassSet(ctx_, bigSet_);
    destroyPassSet(ctx_, orderSet_);
}

RasterTargets RasterPass::plan(FrameGraph& graph, uint32_t samples,
                               const passes::MeshletCull* cull) {
    samples_ = samples;
    cull_ = cull;
    t_.hybrid = hybrid_;
    const VkDeviceSize bytes = VkDeviceSize(graph.width()) * graph.height() * samples * 8;
    if (bytes > ctx_.caps.maxStorageBufferRange)
        throw RendererError("visbuffer: --vis-raster needs " + std::to_string(bytes >> 20) +
                            " MiB of samples in one storage buffer, more than " +
                            ctx_.info.name + "'s " +
                            std::to_string(ctx_.caps.maxStorageBufferRange >> 20) +
                            " MiB; use a lower --res or --msaa");
    t_.samples = graph.createBuffer("vis_raster_samples", bytes,
                                    "per sample: depth bits and ~id, the 64-bit atomic max");
    makeChunks();
    const VkDeviceSize slots = std::max(triangles_, 1u), chunks = std::max(chunkCount_, 1u);
    if (hybrid_) {
        t_.list = graph.createBuffer(
            "vis_raster_list", (TP_VR_LIST_HEADER + chunks + 4 * TP_VR_GROUP * chunks) * 4,
            "counters, then per chunk of triangles its listed count and a slot for each");
        t_.hwList = graph.createBuffer("vis_raster_hw_list", 4 * slots * 4,
                                       "per listed triangle its vertices and id, in draw order");
    } else {
        t_.list = graph.createBuffer(
            "vis_raster_list", (TP_VR_LIST_HEADER + 4 * slots) * 4,
            "counters, then per large triangle its vertices and id (a slot for every triangle)");
    }
    t_.args = graph.createBuffer("vis_raster_args", 16,
                                 hybrid_ ? "the hardware's draw of the listed triangles"
                                         : "vis_raster_big's dispatch");
    graph.addPass("vis_raster_clear",
                  {{t_.samples, Use::TransferDst}, {t_.list, Use::TransferDst},
                   {t_.args, Use::TransferDst}},
                  [this](PassContext& pc) {
                      vkCmdFillBuffer(pc.cmd, pc.buffer(t_.samples).buffer, 0, VK_WHOLE_SIZE, 0);
                      vkCmdFillBuffer(pc.cmd, pc.buffer(t_.list).buffer, 0,
                                      TP_VR_LIST_HEADER * 4, 0);
                      // Compute: groups {0, 1, 1}; hybrid: {0 vertices, 1 instance, 0, 0}.
                      const uint32_t args[4] = {0, 1, hybrid_ ? 0u : 1u, 0};
                      vkCmdUpdateBuffer(pc.cmd, pc.buffer(t_.args).buffer, 0, sizeof(args), args);
                  });
    std::vector<PassUse> uses{{t_.samples, Use::StorageWrite, TP_VR_BINDING_SAMPLES},
                              {t_.list, Use::StorageWrite, TP_VR_BINDING_LIST},
                              {t_.args, Use::StorageWrite, TP_VR_BINDING_ARGS}};
    if (cull) {
        uses.push_back({cull->commands(), Use::StorageRead, TP_VR_BINDING_COMMANDS});
        uses.push_back({cull->counts(), Use::StorageRead, TP_VR_BINDING_COUNTS});
    }
    graph.addPass("vis_raster", uses, [this](PassContext& pc) { record(pc); });
    if (hybrid_)
        graph.addPass("vis_raster_order",
                      {{t_.list, Use::StorageRead, TP_VR_BINDING_ORDER_STAGED},
                       {t_.hwList, Use::StorageWrite, TP_VR_BINDING_ORDER_LIST},
                       {t_.args, Use::StorageWrite, TP_VR_BINDING_ORDER_ARGS}},
                      [this](PassContext& pc) { recordOrder(pc); });
    if (!hybrid_)
        graph.addPass("vis_raster_big",
                      {{t_.samples, Use::StorageWrite, TP_VR_BINDING_SAMPLES},
                       {t_.list, Use::StorageWrite, TP_VR_BINDING_LIST}, // its atomics' count
                       {t_.args, Use::IndirectRead}},
                      [this](PassContext& pc) { recordBig(pc); });
    graph.exportResource("vis_raster_list", t_.list);
    if (hybrid_) graph.exportResource("vis_raster_hw_list", t_.hwList);
    return t_;
}

// One chunk per TP_VR_GROUP triangles of a draw, or per meshlet the cull may keep.
void RasterPass::makeChunks() {
    std::vector<gpu::RasterChunk> chunks;
    for (const TableDraw& t : draws_) {
        const DrawItem& d = *t.item;
        if (cull_) {
            const uint32_t slot = cull_->slot(d), first = cull_->firstCommand(slot);
            for (uint32_t k = 0; k < d.meshletCount; ++k)
                chunks.push_back({t.row, slot, 0, first + k, k, 0, 0, 0});
            continue;
        }
        const uint32_t triangles = d.indexCount / 3;
        for (uint32_t first = 0; first < triangles; first += TP_VR_GROUP)
            chunks.push_back({t.row, d.firstIndex, d.vertexOffset, first,
                              std::min<uint32_t>(TP_VR_GROUP, triangles - first), 0, 0, 0});
    }
    chunkCount_ = uint32_t(chunks.size());
    if (chunks.empty()) chunks.push_back({}); // a buffer of one: no group reads it
    chunkData_ = std::move(chunks);
}

void RasterPass::prepare(FrameGraph& graph) {
    chunks_ = createBufferWithData(ctx_, chunkData_.data(),
                                   chunkData_.size() * sizeof(gpu::RasterChunk),
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                   {graph.owner(), "", "vis_raster_chunks",
                                    "per workgroup of vis_raster: its draw row and triangles"});
    chunkData_ = {};
    std::vector<gpu::RasterRow> rows(table_.rows.size(), gpu::RasterRow{0, 0});
    for (const TableDraw& t : draws_)
        rows.at(t.row) = {(t.item->doubleSided ? TP_VR_FLAG_DOUBLE_SIDED : 0u) |
                              (t.item->alphaMode == AlphaMode::Mask ? TP_VR_FLAG_MASKED : 0u),
                          t.item->material};
    rows_ = createBufferWithData(ctx_, rows.data(), rows.size() * sizeof(gpu::RasterRow),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                 {graph.owner(), "", "vis_raster_rows",
                                  "per draw row: double-sided and masked flags, material"});
    std::vector<ExternalBuffer> externals{
        {TP_VR_BINDING_INDICES, cull_ ? scene_.meshletIndexBuffer() : scene_.indexBuffer()},
        {TP_VR_BINDING_CHUNKS, chunks_.buffer},
        {TP_VR_BINDING_ROWS, rows_.buffer}};
    if (cull_)
        externals.push_back(
            {TP_VR_BINDING_SOURCE_TRIANGLES, scene_.meshletSourceTriangleBuffer()});
    set_ = graph.createPassSet("vis_raster", VK_NULL_HANDLE, externals);
    layout_ = scene_.createPipelineLayout(set_.layout);
    std::vector<SpecConstant> spec = scene_.specConstants(AlphaMode::Mask);
    spec.push_back({TP_SPEC_SAMPLES, samples_});
    spec.push_back({TP_VIS_SPEC_TRIANGLE_BITS, table_.triangleBits});
    spec.push_back({TP_VR_SPEC_HYBRID, hybrid_ ? 1u : 0u});
    const std::vector<SpecConstant> triangle = rasterTriangleConstants(ctx_);
    spec.insert(spec.end(), triangle.begin(), triangle.end());
    pipeline_ = createComputePipeline(ctx_, cull_ ? "vis_raster_meshlet_comp" : "vis_raster_comp",
                                      spec, layout_, &set_);
    if (hybrid_) {
        orderSet_ = graph.createPassSet("vis_raster_order");
        orderLayout_ = scene_.createPipelineLayout(orderSet_.layout);
        order_ = createComputePipeline(ctx_, "vis_raster_order_comp",
                                       {{TP_VR_SPEC_CHUNKS, std::max(chunkCount_, 1u)}},
                                       orderLayout_, &orderSet_);
        return;
    }
    bigSet_ = graph.createPassSet("vis_raster_big", VK_NULL_HANDLE,
                                  {{TP_VR_BINDING_ROWS, rows_.buffer}});
    bigLayout_ = scene_.createPipelineLayout(bigSet_.layout);
    big_ = createComputePipeline(ctx_, "vis_raster_big_comp", spec, bigLayout_, &bigSet_);
}

void RasterPass::record(PassContext& pc) {
    if (chunkCount_ == 0) return;
    // No push constants (meshlet_cull.cpp: lavapipe's queue thread and a push before the
    // frame's first graphics pipeline); the group's chunk is its index in the table.
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_COMPUTE);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    dispatchChunks(pc.cmd);
}

// A workgroup per chunk (vis_raster and vis_raster_order alike).
void RasterPass::dispatchChunks(VkCommandBuffer cmd) const {
    const uint32_t x = std::min(chunkCount_, 65535u);
    vkCmdDispatch(cmd, x, (chunkCount_ + x - 1) / x, 1);
}

void RasterPass::recordOrder(PassContext& pc) {
    if (chunkCount_ == 0) return; // nothing staged: the draw keeps its 0 vertices
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, order_);
    scene_.bindSceneSet(pc.cmd, orderLayout_, VK_PIPELINE_BIND_POINT_COMPUTE);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, orderLayout_, TP_SET_PASS, 1,
                            &orderSet_.set, 0, nullptr);
    dispatchChunks(pc.cmd);
}

void RasterPass::recordBig(PassContext& pc) {
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, big_);
    scene_.bindSceneSet(pc.cmd, bigLayout_, VK_PIPELINE_BIND_POINT_COMPUTE);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, bigLayout_, TP_SET_PASS, 1,
                            &bigSet_.set, 0, nullptr);
    vkCmdDispatchIndirect(pc.cmd, pc.buffer(t_.args).buffer, 0);
}

void RasterPass::collect(FrameGraph& graph) {
    std::vector<uint8_t> raw = readbackBuffer(ctx_, graph.buffer(t_.list));
    std::memcpy(counts_, raw.data(), sizeof(counts_));
    collected_ = true;
}

std::vector<std::pair<std::string, double>> RasterPass::counters() const {
    std::vector<std::pair<std::string, double>> c = {{"raster_triangles", double(triangles_)}};
    if (!collected_) return c;
    c.push_back({"raster_triangles_small", double(counts_[TP_VR_COUNT_SMALL])});
    c.push_back({"raster_triangles_listed", double(counts_[TP_VR_COUNT_BIG])});
    c.push_back({"raster_triangles_culled", double(counts_[TP_VR_COUNT_CULLED])});
    c.push_back({"raster_triangles_clipped", double(counts_[TP_VR_COUNT_CLIPPED])});
    c.push_back({"raster_sample_atomics",
                 double(counts_[TP_VR_ATOMICS_SMALL]) + double(counts_[TP_VR_ATOMICS_BIG])});
    return c;
}

void RasterPass::addWork(RendererStats& s) const {
    if (!collected_) return;
    using Kind = PassOpWork::Kind;
    using Base = PassLightWork::Base;
    s.opWork.push_back({"vis_raster", Kind::Triangles, Base::Items, 1.0, true,
                        "triangles rasterized by their own invocation (raster_triangles_small)",
                        double(counts_[TP_VR_COUNT_SMALL])});
    s.opWork.push_back({"vis_raster", Kind::GlobalAtomics, Base::Items, 1.0, true,
                        "64-bit atomic max per covered sample, counted",
                        double(counts_[TP_VR_ATOMICS_SMALL])});
    if (hybrid_) return;
    s.opWork.push_back({"vis_raster_big", Kind::Triangles, Base::Items, 1.0, true,
                        "listed triangles, a workgroup each (raster_triangles_listed)",
                        double(counts_[TP_VR_COUNT_BIG])});
    s.opWork.push_back({"vis_raster_big", Kind::GlobalAtomics, Base::Items, 1.0, true,
                        "64-bit atomic max per covered sample, counted",
                        double(counts_[TP_VR_ATOMICS_BIG])});
}

} // namespace tp::vis
