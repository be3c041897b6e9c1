#include <optional>

#include "core/gpu/context.h"
#include "core/gpu/rendering.h"
#include "core/passes/meshlet_cull.h"
#include "core/renderer/msaa_knob.h"
#include "multipass_forward/passes.h"

namespace tp::mp {

std::vector<PassUse> shadingUses(const Targets& t, bool resolve, bool stencil) {
    std::vector<PassUse> uses = {{t.color(), Use::ColorAttachment},
                                 {t.depthTarget(), stencil ? Use::DepthAttachment : Use::DepthTest}};
    if (resolve && t.hdrMsaa.valid()) uses.push_back({t.hdr, Use::ColorResolve});
    return uses;
}

void beginShading(PassContext& pc, const Targets& t, bool resolve, bool clear, bool stencil) {
    ColorTarget color{t.color(), resolve && t.hdrMsaa.valid() ? t.hdr : ResourceHandle{}, clear};
    DepthTarget depth{t.depthTarget(), {}, false, !stencil};
    depth.stencil = stencil;
    beginRendering(pc, {color}, depth);
}

GraphicsPipelineDesc shadingDesc(const PassEnv& env, AlphaMode mode) {
    GraphicsPipelineDesc d;
    d.specConstants = env.scene.specConstants(mode);
    d.colorFormats = {env.accumFormat};
    d.depthFormat = kDepthFormat;
    d.samples = VkSampleCountFlagBits(env.settings.sampling.samples);
    d.sampleShading = env.settings.sampling.perSample(); // --msaa-shading sample
    d.layout = env.layout;
    return d;
}

std::string fragmentShader(const PassEnv& env, const std::string& stem) {
    return "mp_" + stem + (env.settings.sampling.perPixelUnderMsaa() ? "_pixel" : "") + "_frag";
}

void bindSceneDraws(VkCommandBuffer cmd, const PassEnv& env, VkPipeline pipeline) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    env.scene.bindSceneSet(cmd, env.layout, VK_PIPELINE_BIND_POINT_GRAPHICS);
    if (env.cull)
        env.scene.bindMeshletIndexBuffer(cmd);
    else
        env.scene.bindIndexBuffer(cmd);
}

void drawOpaque(PassContext& pc, const PassEnv& env, const DrawItem& d, uint32_t pad0) {
    if (env.cull)
        env.cull->recordDraw(pc, env.layout, d, pad0);
    else
        recordDraw(pc.cmd, env.layout, d, pad0);
}

void setScissor(VkCommandBuffer cmd, const ScreenRect& r) {
    VkRect2D rect{{r.x0, r.y0}, {uint32_t(r.x1 - r.x0), uint32_t(r.y1 - r.y0)}};
    vkCmdSetScissor(cmd, 0, 1, &rect);
}

void destroyPipeline(GpuContext& ctx, VkPipeline& pipeline) {
    if (pipeline) vkDestroyPipeline(ctx.device, pipeline, nullptr);
    pipeline = VK_NULL_HANDLE;
}

} // namespace tp::mp
