#include "visbuffer/visibility_pass.h"

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/rendering.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/meshlet_cull.h"
#include "core/renderer/renderer.h"

namespace tp::vis {

VisibilityPass::~VisibilityPass() {
    if (opaque_) vkDestroyPipeline(ctx_.device, opaque_, nullptr);
    if (masked_) vkDestroyPipeline(ctx_.device, masked_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    destroyPassSet(ctx_, set_);
}

VisibilityTargets VisibilityPass::createTargets(FrameGraph& graph, uint32_t samples,
                                                ResourceHandle resolvedDepth) {
    samples_ = samples;
    resolved_ = resolvedDepth;
    const auto count = VkSampleCountFlagBits(samples);
    t_.ids = graph.createImage("visibility_ids",
                               {VK_FORMAT_R32_SFLOAT, 0, 0, count,
                                "packed (draw, triangle) id per sample as an exact fp32 "
                                "integer (0: no geometry)"});
    t_.depth = samples > 1 ? graph.createImage("visibility_depth_msaa",
                                               {VK_FORMAT_D32_SFLOAT, 0, 0, count,
                                                "per-sample depth (reverse-Z)"})
                           : resolvedDepth;
    return t_;
}

void VisibilityPass::plan(FrameGraph& graph, const VisibilityTargets& targets,
                          passes::MeshletCull* cull, Draws draws, bool seeded, bool keepIds) {
    t_ = targets;
    draws_ = draws;
    cull_ = cull;
    seeded_ = seeded;
    // Only this pass writes the ids and the depth: where it leaves a sample, the depth says so.
    // (The compute rasterizer's merge and seed write them too, and are left as they were.)
    idsByDepth_ = draws == Draws::All && !seeded && !keepIds;
    if (draws == Draws::None) return; // compute mode: the seed or the merge writes the targets
    // The ids zeroed (no geometry) by compute where the device can store to them.
    if (!seeded_ && !idsByDepth_) idsClear_.plan(graph, "visibility_ids_clear", t_.ids, {});
    std::vector<PassUse> uses{{t_.ids, Use::ColorAttachment}, {t_.depth, Use::DepthAttachment}};
    // With the compute rasterizer the merge after this pass resolves.
    if (samples_ > 1 && draws == Draws::All) uses.push_back({resolved_, Use::DepthResolve});
    passes::planGeometryPass(
        graph, cull, "visibility", uses, t_.depth,
        [this](PassContext& pc, passes::CullPhase phase) { record(pc, phase); });
}

void VisibilityPass::prepare(FrameGraph& graph) {
    if (draws_ == Draws::None) return;
    idsClear_.prepare(graph);
    GraphicsPipelineDesc d;
    // Culled: the map from meshlet order back to each draw's triangles, in set 1.
    const std::string meshlets = cull_ ? "_meshlet" : "";
    if (cull_) {
        set_ = graph.createPassSet(
            "visibility", VK_NULL_HANDLE,
            {{TP_VIS_BINDING_SOURCE_TRIANGLES, scene_.meshletSourceTriangleBuffer()}});
        d.passSet = &set_;
    }
    layout_ = scene_.createPipelineLayout(cull_ ? set_.layout : VK_NULL_HANDLE);
    d.colorFormats = {VK_FORMAT_R32_SFLOAT};
    d.samples = VkSampleCountFlagBits(samples_);
    d.layout = layout_;
    if (!table_.opaque.empty() && draws_ == Draws::All) {
        // Opaque: no material, so scene.vert's position-only variant (the same gl_Position).
        d.vertexShader = "scene_position" + meshlets + "_vert";
        d.fragmentShader = "vis_visibility" + meshlets + "_frag";
        d.specConstants = scene_.specConstants(AlphaMode::Opaque);
        d.specConstants.push_back({TP_VIS_SPEC_TRIANGLE_BITS, table_.triangleBits});
        opaque_ = createGraphicsPipeline(ctx_, d);
    }
    if (!table_.masked.empty()) {
        // Masked: the alpha test per sample (`sample` inputs), as prepass_mask.frag.
        d.vertexShader = "scene" + meshlets + "_vert";
        d.fragmentShader = "vis_visibility_masked" + meshlets + "_frag";
        d.sampleShading = samples_ > 1;
        d.specConstants = scene_.specConstants(AlphaMode::Mask);
        d.specConstants.push_back({TP_VIS_SPEC_TRIANGLE_BITS, table_.triangleBits});
        masked_ = createGraphicsPipeline(ctx_, d);
    }
}

void VisibilityPass::record(PassContext& pc, passes::CullPhase phase) {
    // The late phase adds to the early's; seeded, to the compute rasterizer's.
    const bool clear = !seeded_ && phase != passes::CullPhase::Late;
    ColorTarget ids{t_.ids, {}, clear && !idsClear_.planned() && !idsByDepth_, {}}; // else by compute
    ids.clearValue.uint32[0] = 0; // no geometry
    ids.dontCare = clear && idsByDepth_; // the late phase loads the early phase's ids
    DepthTarget depth{t_.depth,
                      samples_ > 1 && draws_ == Draws::All ? resolved_ : ResourceHandle{}, clear};
    beginRendering(pc, {ids}, depth);
    scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
    if (cull_) {
        vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, TP_SET_PASS, 1,
                                &set_.set, 0, nullptr);
        scene_.bindMeshletIndexBuffer(pc.cmd);
    } else {
        scene_.bindIndexBuffer(pc.cmd);
    }
    auto drawAll = [&](VkPipeline pipeline, const std::vector<TableDraw>& draws) {
        if (!pipeline) return;
        vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        for (const TableDraw& t : draws)
            if (cull_)
                cull_->recordDraw(pc, layout_, *t.item, t.row, phase);
            else
                recordDraw(pc.cmd, layout_, *t.item, t.row);
    };
    drawAll(opaque_, table_.opaque);
    drawAll(masked_, table_.masked);
    endRendering(pc);
}

} // namespace tp::vis
