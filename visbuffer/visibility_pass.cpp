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
    if (merge_) vkDestroyPipeline(ctx_.device, merge_, nullptr);
    if (listed_) vkDestroyPipeline(ctx_.device, listed_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    destroyPassSet(ctx_, set_);
}

VisibilityTargets VisibilityPass::plan(FrameGraph& graph, uint32_t samples,
                                       ResourceHandle resolvedDepth,
                                       const passes::MeshletCull* cull,
                                       const RasterTargets& raster) {
    samples_ = samples;
    raster_ = raster;
    resolved_ = resolvedDepth;
    cull_ = cull;
    const auto count = VkSampleCountFlagBits(samples);
    t_.ids = graph.createImage("visibility_ids",
                               {VK_FORMAT_R32_SFLOAT, 0, 0, count,
                                "packed (draw, triangle) id per sample as an exact fp32 "
                                "integer (0: no geometry)"});
    std::vector<PassUse> uses{{t_.ids, Use::ColorAttachment}};
    if (samples > 1) {
        t_.depth = graph.createImage("visibility_depth_msaa", {VK_FORMAT_D32_SFLOAT, 0, 0, count,
                                                               "per-sample depth (reverse-Z)"});
        uses.push_back({t_.depth, Use::DepthAttachment});
        uses.push_back({resolvedDepth, Use::DepthResolve});
    } else {
        t_.depth = resolvedDepth;
        uses.push_back({resolvedDepth, Use::DepthAttachment});
    }
    // Compute mode draws no scene draw here, so it needs none of the cull's commands.
    if (cull && (!raster.valid() || raster.hybrid))
        for (const PassUse& u : cull->drawUses())
            uses.push_back(u);
    if (raster.valid()) {
        uses.push_back({raster.samples, Use::StorageRead, TP_VR_BINDING_VIS_SAMPLES});
        if (raster.hybrid) {
            uses.push_back({raster.list, Use::StorageRead, TP_VR_BINDING_VIS_LIST});
            uses.push_back({raster.args, Use::IndirectRead});
        }
    }
    graph.addPass("visibility", uses, [this](PassContext& pc) { record(pc); });
    return t_;
}

void VisibilityPass::prepare(FrameGraph& graph) {
    GraphicsPipelineDesc d;
    // Culled: the map from meshlet order back to each draw's triangles, in set 1.
    const std::string meshlets = cull_ ? "_meshlet" : "";
    if (cull_ || raster_.valid()) {
        std::vector<ExternalBuffer> externals;
        if (cull_)
            externals.push_back(
                {TP_VIS_BINDING_SOURCE_TRIANGLES, scene_.meshletSourceTriangleBuffer()});
        set_ = graph.createPassSet("visibility", VK_NULL_HANDLE, externals);
        d.passSet = &set_;
    }
    layout_ = scene_.createPipelineLayout(d.passSet ? set_.layout : VK_NULL_HANDLE);
    d.colorFormats = {VK_FORMAT_R32_SFLOAT};
    d.samples = VkSampleCountFlagBits(samples_);
    d.layout = layout_;
    if (raster_.valid()) prepareRaster(d);
    // Compute mode: every opaque and masked triangle is the rasterizer's; hybrid: the opaque.
    const bool hardwareOpaque = !raster_.valid();
    const bool hardwareMasked = !raster_.valid() || raster_.hybrid;
    if (!table_.opaque.empty() && hardwareOpaque) {
        // Opaque: no material, so scene.vert's position-only variant (the same gl_Position).
        d.vertexShader = "scene_position" + meshlets + "_vert";
        d.fragmentShader = "vis_visibility" + meshlets + "_frag";
        d.specConstants = scene_.specConstants(AlphaMode::Opaque);
        d.specConstants.push_back({TP_VIS_SPEC_TRIANGLE_BITS, table_.triangleBits});
        opaque_ = createGraphicsPipeline(ctx_, d);
    }
    if (!table_.masked.empty() && hardwareMasked) {
        // Masked: the alpha test per sample (`sample` inputs), as prepass_mask.frag.
        d.vertexShader = "scene" + meshlets + "_vert";
        d.fragmentShader = "vis_visibility_masked" + meshlets + "_frag";
        d.sampleShading = samples_ > 1;
        d.specConstants = scene_.specConstants(AlphaMode::Mask);
        d.specConstants.push_back({TP_VIS_SPEC_TRIANGLE_BITS, table_.triangleBits});
        masked_ = createGraphicsPipeline(ctx_, d);
    }
}

void VisibilityPass::record(PassContext& pc) {
    ColorTarget ids{t_.ids, {}, true, {}};
    ids.clearValue.uint32[0] = 0; // no geometry
    DepthTarget depth{t_.depth, samples_ > 1 ? resolved_ : ResourceHandle{}};
    beginRendering(pc, {ids}, depth);
    scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
    if (set_.set)
        vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, TP_SET_PASS, 1,
                                &set_.set, 0, nullptr);
    if (cull_) {
        scene_.bindMeshletIndexBuffer(pc.cmd);
    } else {
        scene_.bindIndexBuffer(pc.cmd);
    }
    auto drawAll = [&](VkPipeline pipeline, const std::vector<TableDraw>& draws) {
        if (!pipeline) return;
        vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        for (const TableDraw& t : draws)
            if (cull_)
                cull_->recordDraw(pc, layout_, *t.item, t.row);
            else
                recordDraw(pc.cmd, layout_, *t.item, t.row);
    };
    drawAll(opaque_, table_.opaque);
    drawAll(masked_, table_.masked);
    if (raster_.valid()) recordRaster(pc);
    endRendering(pc);
}

// The merge (every mode of the compute rasterizer) and the hardware's listed triangles
// (hybrid), neither culled by the hardware: vis_raster culled back faces already, per draw.
void VisibilityPass::prepareRaster(GraphicsPipelineDesc d) {
    if (raster_.hybrid) {
        d.vertexShader = "vis_raster_hw_vert";
        d.fragmentShader = "vis_raster_hw_frag";
        d.specConstants = scene_.specConstants(AlphaMode::Opaque);
        listed_ = createGraphicsPipeline(ctx_, d);
    }
    d.vertexShader = "vis_raster_merge_vert";
    d.fragmentShader = "vis_raster_merge_frag";
    d.sampleShading = samples_ > 1; // one invocation per sample: each its own (depth, id)
    d.specConstants = scene_.specConstants(AlphaMode::Opaque);
    d.specConstants.push_back({TP_SPEC_SAMPLES, samples_});
    merge_ = createGraphicsPipeline(ctx_, d);
}

void VisibilityPass::recordRaster(PassContext& pc) {
    const gpu::DrawPush push{};
    vkCmdPushConstants(pc.cmd, layout_, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
    vkCmdSetCullMode(pc.cmd, VK_CULL_MODE_NONE);
    if (listed_) {
        vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, listed_);
        vkCmdDrawIndirect(pc.cmd, pc.buffer(raster_.args).buffer, 0, 1, 16);
    }
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, merge_);
    vkCmdDraw(pc.cmd, 3, 1, 0, 0);
}

} // namespace tp::vis
