#include "deferred/gbuffer_pass.h"

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/rendering.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/meshlet_cull.h"
#include "deferred/deferred_shared.h"

namespace tp {

GBufferPass::~GBufferPass() {
    if (opaque_) vkDestroyPipeline(ctx_.device, opaque_, nullptr);
    if (masked_) vkDestroyPipeline(ctx_.device, masked_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    destroyPassSet(ctx_, set_);
}

void GBufferPass::plan(FrameGraph& graph, DeferredTargets& t, passes::MeshletCull* cull,
                       bool prepass) {
    t_ = &t;
    cull_ = cull;
    const auto samples = VkSampleCountFlagBits(t.layout.samples);
    for (const GBufferTarget& c : t.layout.colors)
        t.gbuffer.push_back(graph.createImage(c.name, {c.format, 0, 0, samples, c.purpose}));
    std::vector<PassUse> uses;
    for (ResourceHandle h : t.gbuffer)
        uses.push_back({h, Use::ColorAttachment});
    t.gbufferDepth = t.msaa() ? graph.createImage("gbuffer_depth_msaa",
                                                  {t.layout.depth, 0, 0, samples,
                                                   "per-sample depth (reverse-Z)"})
                              : t.depth;
    if (prepass) {
        // The prepass resolves sample 0 into `depth` under MSAA; this pass only tests.
        passes::DepthPrepassParams p{t.layout.samples, scene_.drawList(DrawFilter::Opaque),
                                     scene_.drawList(DrawFilter::Mask)};
        p.depthFormat = t.layout.depth;
        p.cull = cull;
        prepass_.emplace(ctx_, scene_, std::move(p));
        prepass_->plan(graph, {t.gbufferDepth, t.msaa() ? t.depth : ResourceHandle{}});
        uses.push_back({t.gbufferDepth, Use::DepthTest});
        if (cull)
            for (const PassUse& u : cull->drawUses()) uses.push_back(u);
        graph.addPass("gbuffer", uses,
                      [this](PassContext& pc) { record(pc, passes::CullPhase::Both); });
        return;
    }
    uses.push_back({t.gbufferDepth, Use::DepthAttachment});
    if (t.msaa()) uses.push_back({t.depth, Use::DepthResolve});
    passes::planGeometryPass(
        graph, cull, "gbuffer", uses, t.gbufferDepth,
        [this](PassContext& pc, passes::CullPhase phase) { record(pc, phase); });
}

void GBufferPass::prepare(FrameGraph& graph) {
    if (prepass_) prepass_->prepare();
    materialsUbo_.emplace(ctx_, scene_, graph.owner(), "materials_ubo"); // not a G-buffer target
    set_ = graph.createPassSet("gbuffer", VK_NULL_HANDLE,
                               {{TP_DEF_BINDING_MATERIALS_UBO, materialsUbo_->buffer(),
                                 VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}});
    layout_ = scene_.createPipelineLayout(set_.layout);
    GraphicsPipelineDesc d;
    d.passSet = &set_;
    if (prepass_) { // the prepass's depth, as Forward+'s shading tests it
        d.depthCompare = VK_COMPARE_OP_EQUAL;
        d.depthWrite = false;
    }
    const bool perSample = t_->msaa() && t_->sampleRateGBuffer;
    const std::string emissive = t_->layout.emissive ? "_emissive_frag" : "_frag";
    d.sampleShading = perSample;
    for (const GBufferTarget& c : t_->layout.colors)
        d.colorFormats.push_back(c.format);
    d.depthFormat = t_->layout.depth;
    d.samples = VkSampleCountFlagBits(t_->layout.samples);
    d.layout = layout_;
    for (AlphaMode mode : {AlphaMode::Opaque, AlphaMode::Mask}) {
        if (!scene_.hasDraws(DrawFilter(mode))) continue;
        // Masked draws once per pixel under MSAA alpha-test every sample (the coverage variant),
        // so they cover what the per-sample masked prepass of the other pipelines covers.
        const bool coverage = mode == AlphaMode::Mask && t_->msaa() && !perSample;
        const char* rate = perSample ? "_sample" : "";
        if (coverage) rate = "_coverage";
        d.fragmentShader = std::string("deferred_gbuffer") + rate + emissive;
        d.specConstants = scene_.specConstants(mode);
        d.specConstants.push_back({TP_DEF_SPEC_WIDE, t_->layout.wide ? 1u : 0u});
        d.specConstants.push_back({TP_DEF_SPEC_MATERIALS_UBO, materialsUbo_->active() ? 1u : 0u});
        if (coverage) d.specConstants.push_back({TP_SPEC_SAMPLES, t_->layout.samples});
        (mode == AlphaMode::Opaque ? opaque_ : masked_) = createGraphicsPipeline(ctx_, d);
    }
}

void GBufferPass::record(PassContext& pc, passes::CullPhase phase) {
    const bool clear = phase != passes::CullPhase::Late; // the late phase adds to the early's
    std::vector<ColorTarget> colors;
    for (ResourceHandle h : t_->gbuffer)
        colors.push_back({h, {}, clear && t_->clearGBuffer, {{0.0f, 0.0f, 0.0f, 0.0f}},
                          clear && !t_->clearGBuffer});
    DepthTarget depth{t_->gbufferDepth, t_->msaa() ? t_->depth : ResourceHandle{}, clear};
    if (prepass_) depth = {t_->gbufferDepth, {}, false, true};
    beginRendering(pc, colors, depth);
    scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    if (cull_) {
        scene_.bindMeshletIndexBuffer(pc.cmd);
        for (auto [mode, pipeline] :
             {std::pair{DrawFilter::Opaque, opaque_}, std::pair{DrawFilter::Mask, masked_}}) {
            if (!pipeline) continue;
            vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
            for (const DrawItem* d : scene_.drawList(mode))
                cull_->recordDraw(pc, layout_, *d, 0, phase);
        }
    } else {
        scene_.recordDraws(pc.cmd, layout_, DrawFilter::Opaque, opaque_);
        scene_.recordDraws(pc.cmd, layout_, DrawFilter::Mask, masked_);
    }
    endRendering(pc);
}

} // namespace tp
