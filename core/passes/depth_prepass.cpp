#include "core/passes/depth_prepass.h"

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/rendering.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/meshlet_cull.h"

namespace tp::passes {

DepthPrepass::DepthPrepass(GpuContext& ctx, const SceneGpu& scene, DepthPrepassParams params)
    : ctx_(ctx), scene_(scene), params_(std::move(params)) {}

DepthPrepass::~DepthPrepass() {
    for (VkPipeline p : {opaque_, masked_})
        if (p) vkDestroyPipeline(ctx_.device, p, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
}

void DepthPrepass::plan(FrameGraph& graph, DepthPrepassTargets t) {
    t_ = t;
    std::vector<PassUse> uses = {{t.depth, Use::DepthAttachment}};
    if (t.resolve.valid()) uses.push_back({t.resolve, Use::DepthResolve});
    planGeometryPass(graph, params_.cull, "depth_prepass", uses, t.depth,
                     [this](PassContext& pc, CullPhase phase) { record(pc, phase); });
}

void DepthPrepass::prepare() {
    layout_ = scene_.createPipelineLayout();
    GraphicsPipelineDesc d;
    d.samples = VkSampleCountFlagBits(params_.samples);
    d.depthFormat = params_.depthFormat;
    d.layout = layout_;
    const bool every = params_.everyPipeline;
    if (!params_.opaque.empty() || (every && scene_.hasDraws(DrawFilter::Opaque))) {
        d.specConstants = scene_.specConstants(AlphaMode::Opaque);
        opaque_ = createGraphicsPipeline(ctx_, d); // no fragment stage: depth only
    }
    if (!params_.masked.empty() || (every && scene_.hasDraws(DrawFilter::Mask))) {
        d.fragmentShader = "prepass_mask_frag";
        d.sampleShading = params_.samples > 1; // per sample, as the reference
        d.specConstants = scene_.specConstants(AlphaMode::Mask);
        masked_ = createGraphicsPipeline(ctx_, d);
    }
}

bool DepthPrepass::setDraws(std::vector<const DrawItem*> opaque,
                            std::vector<const DrawItem*> masked) {
    if ((!opaque.empty() && !opaque_) || (!masked.empty() && !masked_)) return false;
    params_.opaque = std::move(opaque);
    params_.masked = std::move(masked);
    return true;
}

void DepthPrepass::record(PassContext& pc, CullPhase phase) {
    // The late phase adds to what the early one wrote.
    beginRendering(pc, {}, DepthTarget{t_.depth, t_.resolve, phase != CullPhase::Late});
    scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
    if (params_.cull)
        scene_.bindMeshletIndexBuffer(pc.cmd);
    else
        scene_.bindIndexBuffer(pc.cmd);
    uint32_t& drawn = phase == CullPhase::Late ? lateDraws_ : draws_;
    drawn = 0;
    for (auto [pipeline, list] :
         {std::pair{opaque_, &params_.opaque}, std::pair{masked_, &params_.masked}}) {
        if (!pipeline) continue;
        vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        for (const DrawItem* d : *list)
            if (params_.cull)
                params_.cull->recordDraw(pc, layout_, *d, 0, phase);
            else
                recordDraw(pc.cmd, layout_, *d);
        drawn += uint32_t(list->size());
    }
    endRendering(pc);
}

} // namespace tp::passes
