#include "core/passes/meshlet_cull.h"

#include <algorithm>
#include <cstring>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/readback.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/depth_pyramid.h"
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
    if (mode == CullGeometry::None) return nullptr;
    cull.emplace(ctx, scene, opaqueAndMaskedDraws(scene), firstTriangle,
                 mode == CullGeometry::Full);
    cull->plan(graph);
    return &*cull;
}

void planGeometryPass(FrameGraph& graph, MeshletCull* cull, const std::string& name,
                      std::vector<PassUse> uses, ResourceHandle depth,
                      std::function<void(PassContext&, CullPhase)> record) {
    auto withDraws = [&](CullPhase phase) {
        std::vector<PassUse> u = uses;
        if (cull)
            for (const PassUse& d : cull->drawUses(phase))
                u.push_back(d);
        return u;
    };
    if (!cull || !cull->occlusion()) {
        graph.addPass(name, withDraws(CullPhase::Both),
                      [record](PassContext& pc) { record(pc, CullPhase::Both); });
        return;
    }
    graph.addPass(name, withDraws(CullPhase::Early),
                  [record](PassContext& pc) { record(pc, CullPhase::Early); });
    cull->planLate(graph, depth);
    graph.addPass(name + "_late", withDraws(CullPhase::Late),
                  [record](PassContext& pc) { record(pc, CullPhase::Late); });
}

MeshletCull::MeshletCull(GpuContext& ctx, SceneGpu& scene, std::vector<const DrawItem*> draws,
                         bool firstTriangle, bool occlusion)
    : ctx_(ctx), scene_(scene), draws_(std::move(draws)), firstTriangle_(firstTriangle),
      occlusion_(occlusion) {
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
    for (Phase* p : {&early_, &late_}) {
        if (p->pipeline) vkDestroyPipeline(ctx_.device, p->pipeline, nullptr);
        if (p->layout) vkDestroyPipelineLayout(ctx_.device, p->layout, nullptr);
        destroyPassSet(ctx_, p->set);
    }
}

void MeshletCull::plan(FrameGraph& graph) {
    const VkDeviceSize slots = std::max<VkDeviceSize>(draws_.size(), 1);
    early_.commands = graph.createBuffer(
        "meshlet_draws",
        std::max<VkDeviceSize>(meshlets_, 1) * TP_MC_COMMAND_WORDS * sizeof(uint32_t),
        occlusion_ ? "per meshlet drawn by the early phase: an indexed indirect draw (5 words), "
                     "per draw a range"
                   : "per kept meshlet: an indexed indirect draw (5 words), per draw a range");
    early_.counts = graph.createBuffer("meshlet_draw_counts", slots * sizeof(uint32_t),
                                      "per draw: its indirect draws this frame");
    early_.stats =
        graph.createBuffer("meshlet_cull_stats", slots * sizeof(gpu::MeshletCullStats),
                           "per draw: meshlets kept, culled by frustum and by cone; triangles");
    graph.addPass("meshlet_cull",
                  {{early_.commands, Use::StorageWrite, TP_MC_BINDING_COMMANDS},
                   {early_.counts, Use::StorageWrite, TP_MC_BINDING_COUNTS},
                   {early_.stats, Use::StorageWrite, TP_MC_BINDING_STATS}},
                  [this](PassContext& pc) { record(pc, early_); });
    graph.exportResource("meshlet_cull_stats", early_.stats);
    early_.planned = true;
}

void MeshletCull::planLate(FrameGraph& graph, ResourceHandle depth) {
    if (!occlusion_ || late_.planned)
        throw RendererError("meshlet_cull: the late phase planned without occlusion or twice");
    pyramid_ = std::make_unique<DepthPyramid>(ctx_, scene_);
    pyramidBuffer_ = pyramid_->plan(graph, depth);
    const VkDeviceSize slots = std::max<VkDeviceSize>(draws_.size(), 1);
    late_.commands = graph.createBuffer(
        "meshlet_draws_late",
        std::max<VkDeviceSize>(meshlets_, 1) * TP_MC_COMMAND_WORDS * sizeof(uint32_t),
        "per meshlet drawn by the late phase: an indexed indirect draw, per draw a range");
    late_.counts = graph.createBuffer("meshlet_draw_counts_late", slots * sizeof(uint32_t),
                                     "per draw: its late indirect draws this frame");
    late_.stats = graph.createBuffer(
        "meshlet_cull_stats_late", slots * sizeof(gpu::MeshletCullStats),
        "per draw: meshlets kept late, culled by frustum, cone and occlusion; triangles");
    graph.addPass("meshlet_cull_late",
                  {{late_.commands, Use::StorageWrite, TP_MC_BINDING_COMMANDS},
                   {late_.counts, Use::StorageWrite, TP_MC_BINDING_COUNTS},
                   {late_.stats, Use::StorageWrite, TP_MC_BINDING_STATS},
                   {pyramidBuffer_, Use::StorageRead, TP_MC_BINDING_PYRAMID}},
                  [this](PassContext& pc) { record(pc, late_); });
    graph.exportResource("meshlet_cull_stats_late", late_.stats);
    late_.planned = true;
}

void MeshletCull::preparePhase(FrameGraph& graph, Phase& p, const std::string& pass,
                               const std::string& shader) {
    std::vector<ExternalBuffer> externals = {{TP_MC_BINDING_MESHLETS, scene_.meshletBuffer()},
                                             {TP_MC_BINDING_DRAWS, table_.buffer}};
    if (occlusion_) externals.push_back({TP_MC_BINDING_HISTORY, history_.buffer});
    p.set = graph.createPassSet(pass, VK_NULL_HANDLE, externals);
    p.layout = scene_.createPipelineLayout(p.set.layout);
    p.pipeline = createComputePipeline(ctx_, shader, scene_.specConstants(AlphaMode::Opaque),
                                       p.layout, &p.set);
}

void MeshletCull::prepare(FrameGraph& graph) {
    if (occlusion_ && !late_.planned)
        throw RendererError("meshlet_cull: occlusion without a late phase (a geometry pass "
                            "that writes depth must plan it: planGeometryPass)");
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
    if (occlusion_) {
        // The first frame treats every meshlet as visible: its early phase draws what the
        // frustum and the cones keep (as --cull-geometry frustum does), so its pyramid is the
        // whole frame's depth and the late phase already finds the hidden ones; the second
        // frame draws the steady state. (None visible would draw everything late against an
        // empty pyramid and settle a frame later.)
        const std::vector<uint32_t> visible(std::max<uint32_t>(meshlets_, 1),
                                            TP_MC_HISTORY_VISIBLE);
        history_ = createBufferWithData(ctx_, visible.data(), visible.size() * sizeof(uint32_t),
                                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                        {graph.owner(), "", "meshlet_visibility",
                                         "per meshlet: visible last frame, drawn early this "
                                         "frame (kept across frames)"});
        pyramid_->prepare(graph);
    }
    preparePhase(graph, early_, "meshlet_cull",
                 occlusion_ ? "meshlet_cull_early_comp" : "meshlet_cull_comp");
    if (occlusion_) preparePhase(graph, late_, "meshlet_cull_late", "meshlet_cull_late_comp");
}

std::vector<PassUse> MeshletCull::drawUses(CullPhase phase) const {
    std::vector<PassUse> uses;
    if (phase != CullPhase::Late || !occlusion_)
        uses = {{early_.commands, Use::IndirectRead}, {early_.counts, Use::IndirectRead}};
    if (occlusion_ && phase != CullPhase::Early) {
        uses.push_back({late_.commands, Use::IndirectRead});
        uses.push_back({late_.counts, Use::IndirectRead});
    }
    return uses;
}

bool MeshletCull::holds(const DrawItem& d) const {
    return d.index < slotOf_.size() && slotOf_[d.index] != ~0u;
}

void MeshletCull::record(PassContext& pc, Phase& p) {
    if (draws_.empty()) return;
    if (occlusion_) {
        // The history words are outside the graph (kept across frames): the early phase
        // follows the last frame's late phase (the same command buffer, submitted again) and
        // the late phase follows this frame's early one.
        memoryBarrier(pc.cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    }
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.pipeline);
    scene_.bindSceneSet(pc.cmd, p.layout, VK_PIPELINE_BIND_POINT_COMPUTE);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.layout, TP_SET_PASS, 1,
                            &p.set.set, 0, nullptr);
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
                             uint32_t pad0, CullPhase phase) const {
    if (!holds(d))
        throw RendererError("meshlet_cull: a draw it was not given (mesh " +
                            std::to_string(d.mesh) + ") recorded as culled");
    const uint32_t slot = slotOf_[d.index];
    gpu::DrawPush push{d.material, pad0, 0, 0};
    vkCmdPushConstants(pc.cmd, layout, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
    vkCmdSetCullMode(pc.cmd, d.doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT);
    constexpr uint32_t stride = TP_MC_COMMAND_WORDS * sizeof(uint32_t);
    auto draw = [&](const Phase& p) {
        vkCmdDrawIndexedIndirectCount(pc.cmd, pc.buffer(p.commands).buffer,
                                      VkDeviceSize(firstCommand_[slot]) * stride,
                                      pc.buffer(p.counts).buffer,
                                      VkDeviceSize(slot) * sizeof(uint32_t), d.meshletCount, stride);
    };
    if (phase != CullPhase::Late) draw(early_);
    if (occlusion_ && phase != CullPhase::Early) draw(late_);
}

void MeshletCull::collect(FrameGraph& graph) {
    keptBySlot_.assign(draws_.size(), 0);
    for (auto [p, totals] : {std::pair{&early_, &earlyTotals_}, std::pair{&late_, &lateTotals_}}) {
        *totals = {};
        if (!p->planned) continue;
        std::vector<uint8_t> bytes = readbackBuffer(ctx_, graph.buffer(p->stats));
        std::vector<gpu::MeshletCullStats> stats(draws_.size());
        std::memcpy(stats.data(), bytes.data(), stats.size() * sizeof(gpu::MeshletCullStats));
        for (size_t i = 0; i < stats.size(); ++i) {
            const gpu::MeshletCullStats& s = stats[i];
            keptBySlot_[i] += s.submitted;
            totals->submitted += s.submitted;
            totals->frustum += s.frustumCulled;
            totals->cone += s.coneCulled;
            totals->occlusion += s.occlusionCulled;
            totals->triangles += s.triangles;
        }
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
    if (!collected_) return c;
    const Totals& e = earlyTotals_;
    const Totals& l = lateTotals_;
    c.push_back({"meshlets_submitted", double(e.submitted + l.submitted)});
    c.push_back({"meshlets_culled_frustum", double(e.frustum + l.frustum)});
    c.push_back({"meshlets_culled_cone", double(e.cone + l.cone)});
    c.push_back({"triangles_submitted", double(e.triangles + l.triangles)});
    if (occlusion_) {
        c.push_back({"meshlets_culled_occlusion", double(l.occlusion)});
        c.push_back({"meshlets_submitted_early", double(e.submitted)});
        c.push_back({"meshlets_submitted_late", double(l.submitted)});
        c.push_back({"triangles_submitted_early", double(e.triangles)});
        c.push_back({"triangles_submitted_late", double(l.triangles)});
    }
    return c;
}

} // namespace tp::passes
