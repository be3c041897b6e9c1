// Depth prepass: after it, every shading pass tests EQUAL, so each sample is shaded once
// per light however deep the scene is. (Forward+ has the same pass; the two could share
// one file later.)
#include "core/gpu/context.h"
#include "core/gpu/rendering.h"
#include "core/render/scene_gpu.h"
#include "multipass_forward/passes.h"

namespace tp::mp {

DepthPrepass::DepthPrepass(const PassEnv& env) : env_(env) {
    GraphicsPipelineDesc d;
    d.samples = VkSampleCountFlagBits(env.settings.msaa);
    d.layout = env.layout;
    if (!env.plan.opaque.empty()) {
        d.specConstants = env.scene.specConstants(AlphaMode::Opaque);
        opaque_ = createGraphicsPipeline(env.ctx, d); // no fragment stage: depth only
    }
    if (!env.plan.masked.empty()) {
        // Per-sample under MSAA, as the reference: the alpha test then sees the same
        // interpolants per sample and the coverage matches.
        d.fragmentShader = "prepass_mask_frag";
        d.sampleShading = env.settings.msaa > 1;
        d.specConstants = env.scene.specConstants(AlphaMode::Mask);
        masked_ = createGraphicsPipeline(env.ctx, d);
    }
}

DepthPrepass::~DepthPrepass() {
    destroyPipeline(env_.ctx, opaque_);
    destroyPipeline(env_.ctx, masked_);
}

std::vector<PassUse> DepthPrepass::uses(const Targets& t) {
    std::vector<PassUse> uses = {{t.depthTarget(), Use::DepthAttachment}};
    if (t.depthMsaa.valid()) uses.push_back({t.depth, Use::DepthResolve});
    return uses;
}

void DepthPrepass::record(PassContext& pc, const Targets& t) {
    DepthTarget depth{t.depthTarget(), t.depthMsaa.valid() ? t.depth : ResourceHandle{}};
    beginRendering(pc, {}, depth);
    const SceneGpu& scene = env_.scene;
    scene.bindSceneSet(pc.cmd, env_.layout, VK_PIPELINE_BIND_POINT_GRAPHICS);
    scene.bindIndexBuffer(pc.cmd);
    draws_ = 0;
    for (auto [pipeline, list] : {std::pair{opaque_, &env_.plan.opaque}, std::pair{masked_, &env_.plan.masked}}) {
        if (!pipeline) continue;
        vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        for (const DrawItem* d : *list) recordDraw(pc.cmd, env_.layout, *d);
        draws_ += uint32_t(list->size());
    }
    endRendering(pc);
}

} // namespace tp::mp
