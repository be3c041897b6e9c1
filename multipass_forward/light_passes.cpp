// One additive pass per local light, all recorded in one graph pass ("light_passes") so
// its GPU time is the cost of lighting as a whole. Each light draws only the meshes its
// sphere touches (planLights), under a scissor at the sphere's screen rectangle; depth
// EQUAL, no writes, blend ONE + ONE into the accumulation target.
#include "core/gpu/context.h"
#include "core/gpu/rendering.h"
#include "core/render/scene_gpu.h"
#include "multipass_forward/passes.h"

namespace tp::mp {

LightPasses::LightPasses(const PassEnv& env) : env_(env) {
    if (!env.allDraws && env.plan.batches.empty()) return;
    GraphicsPipelineDesc d = shadingDesc(env, AlphaMode::Opaque); // masked too: EQUAL test
    d.fragmentShader = fragmentShader(env, "light");
    d.depthWrite = false;
    d.depthCompare = VK_COMPARE_OP_EQUAL;
    d.blend = BlendMode::Additive;
    pipeline_ = createGraphicsPipeline(env.ctx, d);
}

LightPasses::~LightPasses() {
    destroyPipeline(env_.ctx, pipeline_);
}

void LightPasses::record(PassContext& pc, const Targets& t, bool resolve) {
    beginShading(pc, t, resolve, false);
    draws_ = 0;
    if (pipeline_) {
        bindSceneDraws(pc.cmd, env_, pipeline_);
        for (const LightBatch& batch : env_.plan.batches) {
            setScissor(pc.cmd, batch.scissor);
            for (const DrawItem* d : batch.draws)
                recordDraw(pc.cmd, env_.layout, *d, batch.light);
            draws_ += uint32_t(batch.draws.size());
        }
    }
    endRendering(pc);
}

} // namespace tp::mp
