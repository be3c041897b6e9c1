#include "core/passes/meshlet_cull.h"

#include <algorithm>
#include <cstring>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/readback.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/renderer/renderer.h"
#include "passes/meshlet_cull.h"

namespace tp::passes {

std::vector<const DrawItem*> opaqueAndMaskedDraws(const SceneGpu& scene) {
    std::vector<const DrawItem*> draws = scene.drawList(DrawFilter::Opaque);
    for (const DrawItem* d : scene.drawList(DrawFilter::Mask))
        draws.push_back(d);
    return draws;
}

MeshletCull* planOpaqueCull(std::optional<MeshletCull>& cull, GpuContext& ctx, SceneGpu& scene,
                            FrameGraph& graph, CullGeometry mode, bool firstTriangle) {
    if (mode != CullGeometry::Frustum) return nullptr;
    cull.emplace(ctx, scene, opaqueAndMaskedDraws(scene), firstTriangle);
    cull->plan(graph);
    return &*cull;
}

MeshletCull::MeshletCull(GpuContext& ctx, SceneGpu& scene, std::vector<const DrawItem*> draws,
                         bool firstTriangle)
    : ctx_(ctx), scene_(scene), draws_(std::move(draws)), firstTriangle_(firstTriangle) {
    if (!ctx_.caps.drawIndirectCount)
        throw RendererError("--cull-geometry: device '" + ctx_.info.name +
                            "' lacks drawIndirectCount or multiDrawIndirect; use "
                            "--cull-geometry none");
    if (firstTriangle_ && !ctx_.caps.drawIndirectFirstInstance)
        throw RendererError("--cull-geometry: device '" + ctx_.info.name +
                            "' lacks drawIndirectFirstInstance; use --cull-geometry none");
    scene.buildMeshlets(); // fills the draws' meshlet ranges in place
    slotOf_.assign(scene_.draws().size(), ~0u);
    uint32_t commands = 0;
    for (const DrawItem* d : draws_) {
        slotOf_.at(d->index) = uint32_t(firstCommand_.size());
        firstCommand_.push_back(commands);
        commands += d->meshletCount;
        meshlets_ += d->meshletCount;
        triangles_ += d->indexCount / 3;
    }
}

MeshletCull::~MeshletCull() {
    if (pipeline_) vkDestroyPipeline(ctx_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    destroyPassSet(ctx_, set_);
}

void MeshletCull::plan(FrameGraph& graph) {
    const VkDeviceSize slots = std::max<VkDeviceSize>(draws_.size(), 1);
    commands_ = graph.createBuffer(
        "meshlet_draws",
        std::max<VkDeviceSize>(meshlets_, 1) * TP_MC_COMMAND_WORDS * sizeof(uint32_t),
        "per kept meshlet: an indexed indirect draw (5 words), per draw a range");
    counts_ = graph.createBuffer("meshlet_draw_counts", slots * sizeof(uint32_t),
                                 "per draw: its indirect draws this frame");
    stats_ =
        graph.createBuffer("meshlet_cull_stats", slots * sizeof(gpu::MeshletCullStats),
                           "per draw: meshlets kept, culled by frustum and by cone; triangles");
    graph.addPass("meshlet_cull",
                  {{commands_, Use::StorageWrite, TP_MC_BINDING_COMMANDS},
                   {counts_, Use::StorageWrite, TP_MC_BINDING_COUNTS},
                   {stats_, Use::StorageWrite, TP_MC_BINDING_STATS}},
                  [this](PassContext& pc) { record(pc); });
    graph.exportResource("meshlet_cull_stats", stats_);
}

void MeshletCull::prepare(FrameGraph& graph) {
    std::vector<gpu::CullDraw> rows;
    for (const DrawItem* d : draws_) {
        gpu::CullDraw r{};
        r.firstMeshlet = d->firstMeshlet;
        r.meshletCount = d->meshletCount;
        r.firstCommand = firstCommand_[rows.size()];
        r.vertexOffset = d->vertexOffset;
        r.flags = d->doubleSided ? 0u : TP_MC_FLAG_CONE; // never cone-cull a double-sided one
        if (firstTriangle_) r.flags |= TP_MC_FLAG_FIRST_TRIANGLE;
        rows.push_back(r);
    }
    if (rows.empty()) rows.push_back({}); // a buffer of one row: no group reads it
    table_ = createBufferWithData(ctx_, rows.data(), rows.size() * sizeof(gpu::CullDraw),
                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                  {graph.owner(), "", "meshlet_cull_draws",
                                   "per culled draw: its meshlets, its range of commands"});
    set_ = graph.createPassSet(
        "meshlet_cull", VK_NULL_HANDLE,
        {{TP_MC_BINDING_MESHLETS, scene_.meshletBuffer()}, {TP_MC_BINDING_DRAWS, table_.buffer}});
    layout_ = scene_.createPipelineLayout(set_.layout);
    pipeline_ = createComputePipeline(ctx_, "meshlet_cull_comp",
                                      scene_.specConstants(AlphaMode::Opaque), layout_, &set_);
}

std::vector<PassUse> MeshletCull::drawUses() const {
    return {{commands_, Use::IndirectRead}, {counts_, Use::IndirectRead}};
}

bool MeshletCull::holds(const DrawItem& d) const {
    return d.index < slotOf_.size() && slotOf_[d.index] != ~0u;
}

void MeshletCull::record(PassContext& pc) {
    if (draws_.empty()) return;
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_COMPUTE);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    // No push constants: the shader takes the draw count from its table's length. On lavapipe
    // (Mesa 22.3) a push to the layout's VK_SHADER_STAGE_ALL range followed by a dispatch,
    // before any graphics pipeline was bound in the command buffer (this pass runs first in
    // the frame), crashes the driver's queue thread (found 2026-11-28; docs/geometry.md).
    // One group per draw, at most 65,535 groups per row (the smallest limit Vulkan allows).
    const uint32_t groups = uint32_t(draws_.size());
    const uint32_t x = std::min(groups, 65535u);
    vkCmdDispatch(pc.cmd, x, (groups + x - 1) / x, 1);
}

void MeshletCull::recordDraw(PassContext& pc, VkPipelineLayout layout, const DrawItem& d,
                             uint32_t pad0) const {
    if (!holds(d))
        throw RendererError("meshlet_cull: a draw it was not given (mesh " +
                            std::to_string(d.mesh) + ") recorded as culled");
    const uint32_t slot = slotOf_[d.index];
    gpu::DrawPush push{d.material, pad0, 0, 0};
    vkCmdPushConstants(pc.cmd, layout, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
    vkCmdSetCullMode(pc.cmd, d.doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT);
    constexpr uint32_t stride = TP_MC_COMMAND_WORDS * sizeof(uint32_t);
    vkCmdDrawIndexedIndirectCount(
        pc.cmd, pc.buffer(commands_).buffer, VkDeviceSize(firstCommand_[slot]) * stride,
        pc.buffer(counts_).buffer, VkDeviceSize(slot) * sizeof(uint32_t), d.meshletCount, stride);
}

void MeshletCull::collect(FrameGraph& graph) {
    std::vector<uint8_t> bytes = readbackBuffer(ctx_, graph.buffer(stats_));
    std::vector<gpu::MeshletCullStats> stats(draws_.size());
    std::memcpy(stats.data(), bytes.data(), stats.size() * sizeof(gpu::MeshletCullStats));
    submitted_ = frustum_ = cone_ = trianglesSubmitted_ = 0;
    keptBySlot_.clear();
    for (const gpu::MeshletCullStats& s : stats) {
        keptBySlot_.push_back(s.submitted);
        submitted_ += s.submitted;
        frustum_ += s.frustumCulled;
        cone_ += s.coneCulled;
        trianglesSubmitted_ += s.triangles;
    }
    collected_ = true;
}

uint32_t MeshletCull::kept(const DrawItem& d) const {
    if (!holds(d)) return 0;
    const uint32_t slot = slotOf_[d.index];
    return slot < keptBySlot_.size() ? keptBySlot_[slot] : 0;
}

std::vector<std::pair<std::string, double>> MeshletCull::counters() const {
    std::vector<std::pair<std::string, double>> c = {{"meshlets", double(meshlets_)},
                                                     {"triangles", double(triangles_)}};
    if (collected_) {
        c.push_back({"meshlets_submitted", double(submitted_)});
        c.push_back({"meshlets_culled_frustum", double(frustum_)});
        c.push_back({"meshlets_culled_cone", double(cone_)});
        c.push_back({"triangles_submitted", double(trianglesSubmitted_)});
    }
    return c;
}

} // namespace tp::passes
