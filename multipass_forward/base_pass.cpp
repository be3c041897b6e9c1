// Base pass: starts the accumulation with ambient + emissive + the directional lights of
// every opaque and masked sample (depth EQUAL against the prepass, no depth writes).
#include "core/gpu/context.h"
#include "core/gpu/rendering.h"
#include "core/gpuscene/scene_gpu.h"
#include "multipass_forward/passes.h"

namespace tp::mp {

// The directional lights the base pass evaluates, as specialization constants.
std::vector<SpecConstant> directionalSpec(const LightPlan& plan) {
    std::vector<SpecConstant> spec = {
        {TP_MP_SPEC_DIRECTIONAL_COUNT, uint32_t(plan.baseDirectional.size())}};
    for (size_t i = 0; i < plan.baseDirectional.size(); ++i)
        spec.push_back({uint32_t(TP_MP_SPEC_DIRECTIONAL_FIRST + i), plan.baseDirectional[i]});
    return spec;
}

BasePass::BasePass(const PassEnv& env) : env_(env) {
    if (!env.allDraws && env.plan.opaque.empty() && env.plan.masked.empty()) return; // only clears
    // Masked draws need no discard here: the EQUAL test only passes where the prepass kept
    // the sample, so one pipeline serves both alpha modes.
    GraphicsPipelineDesc d = shadingDesc(env, AlphaMode::Opaque);
    for (SpecConstant c : directionalSpec(env.plan))
        d.specConstants.push_back(c);
    d.fragmentShader = fragmentShader(env, "base");
    d.depthWrite = false;
    d.depthCompare = VK_COMPARE_OP_EQUAL;
    pipeline_ = createGraphicsPipeline(env.ctx, d);
}

BasePass::~BasePass() {
    destroyPipeline(env_.ctx, pipeline_);
}

void BasePass::record(PassContext& pc, const Targets& t, bool resolve, bool clear) {
    beginShading(pc, t, resolve, clear);
    draws_ = 0;
    if (pipeline_) {
        bindSceneDraws(pc.cmd, env_, pipeline_);
        for (const auto* list : {&env_.plan.opaque, &env_.plan.masked}) {
            for (const DrawItem* d : *list)
                drawOpaque(pc, env_, *d);
            draws_ += uint32_t(list->size());
        }
    }
    endRendering(pc);
}

} // namespace tp::mp
