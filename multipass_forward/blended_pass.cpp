// Blended surfaces, back to front, one draw at a time: its base pass composites
// ambient + emissive + directional lights over what is behind it (alpha blending), then
// each light that touches it adds alpha * light (the light shader scales by alpha, blend
// ONE + ONE). Finishing one draw before the next makes overlapping draws composite as in
// the reference; only a draw that overlaps itself on screen differs (docs/multipass_forward.md).
#include "core/gpu/context.h"
#include "core/gpu/rendering.h"
#include "core/render/scene_gpu.h"
#include "multipass_forward/passes.h"

namespace tp::mp {

std::vector<SpecConstant> directionalSpec(const LightPlan& plan); // base_pass.cpp

BlendedPass::BlendedPass(const PassEnv& env) : env_(env) {
    if (env.plan.blended.empty()) return;
    // Depth GREATER against the opaque depth, no writes: as the reference draws them.
    GraphicsPipelineDesc d = shadingDesc(env, AlphaMode::Blend);
    d.depthWrite = false;
    GraphicsPipelineDesc base = d;
    for (SpecConstant c : directionalSpec(env.plan)) base.specConstants.push_back(c);
    base.fragmentShader = "mp_base_frag";
    base.blend = BlendMode::Alpha;
    base_ = createGraphicsPipeline(env.ctx, base);
    d.fragmentShader = "mp_light_frag";
    d.blend = BlendMode::Additive;
    light_ = createGraphicsPipeline(env.ctx, d);
}

BlendedPass::~BlendedPass() {
    destroyPipeline(env_.ctx, base_);
    destroyPipeline(env_.ctx, light_);
}

void BlendedPass::record(PassContext& pc, const Targets& t, bool resolve) {
    beginShading(pc, t, resolve, false);
    const SceneGpu& scene = env_.scene;
    scene.bindSceneSet(pc.cmd, env_.layout, VK_PIPELINE_BIND_POINT_GRAPHICS);
    scene.bindIndexBuffer(pc.cmd);
    const ScreenRect full{0, 0, int32_t(env_.settings.width), int32_t(env_.settings.height)};
    draws_ = 0;
    for (const BlendedDraw& b : env_.plan.blended) {
        vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, base_);
        setScissor(pc.cmd, full);
        recordDraw(pc.cmd, env_.layout, *b.draw);
        if (!b.lights.empty()) vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, light_);
        for (const auto& [light, scissor] : b.lights) {
            setScissor(pc.cmd, scissor);
            recordDraw(pc.cmd, env_.layout, *b.draw, light);
        }
        draws_ += 1 + uint32_t(b.lights.size());
    }
    endRendering(pc);
}

} // namespace tp::mp
