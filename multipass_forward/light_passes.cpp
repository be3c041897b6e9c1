// One additive pass per local light, all recorded in one graph pass ("light_passes") so
// its GPU time is the cost of lighting as a whole. Each light draws only the meshes its
// sphere touches (planLights), under a scissor at the sphere's screen rectangle; depth
// EQUAL, no writes, blend ONE + ONE into the accumulation target. With --shadows, a shadowed
// light's map is rendered right before its draws (shadowed_shading.cpp), timed with them.
//
// Coincident surfaces (a mesh instanced twice at one transform, overlapping coplanar
// triangles) all pass depth EQUAL where the prepass's GREATER kept one of them, so additive
// blending would add the light once per surface (a cube face of a real scene was lit twice:
// docs/multipass_forward.md). Each light's draws therefore write its tag into the stencil and
// pass only where the stencil does not hold it yet: a sample takes each light once.
#include "core/gpu/context.h"
#include "core/gpu/rendering.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/shadow_maps.h"
#include "multipass_forward/light_draw_pass.h"
#include "multipass_forward/multipass_shared.h"
#include "multipass_forward/passes.h"

namespace tp::mp {
namespace {

constexpr uint32_t kMaxStencilTag = 255; // 8 stencil bits; 0 is "no light yet"

// Every 255 lights the tags start again from a cleared stencil (inside the rendering).
void clearStencil(PassContext& pc, const Targets& t) {
    const Image& depth = pc.image(t.depthTarget());
    VkClearAttachment clear{VK_IMAGE_ASPECT_STENCIL_BIT, 0, {}};
    VkClearRect rect{{{0, 0}, {depth.desc.width, depth.desc.height}}, 0, 1};
    vkCmdClearAttachments(pc.cmd, 1, &clear, 1, &rect);
}

} // namespace

LightPasses::LightPasses(const PassEnv& env, const PassSet* litSet)
    : env_(env), litSet_(litSet ? litSet->set : VK_NULL_HANDLE) {
    if (!env.allDraws && env.plan.batches.empty()) return;
    const bool count = litSet != nullptr;
    GraphicsPipelineDesc d = shadingDesc(env, AlphaMode::Opaque); // masked too: EQUAL test
    d.fragmentShader = fragmentShader(env, count ? "light_count" : "light");
    if (count) d.passSet = litSet;
    d.depthWrite = false;
    d.depthCompare = VK_COMPARE_OP_EQUAL;
    d.blend = BlendMode::Additive;
    d.stencilOnce = true;
    if (env.lightDraws) { // GPU lists: the material from each command's firstInstance
        d.vertexShader = "scene_material_vert";
        d.fragmentShader = fragmentShader(env, count ? "light_inst_count" : "light_inst");
    }
    pipeline_ = createGraphicsPipeline(env.ctx, d);
    shadowed_ = createShadowedTwin(env, d);
}

LightPasses::~LightPasses() {
    destroyPipeline(env_.ctx, pipeline_);
    destroyPipeline(env_.ctx, shadowed_);
}

// With --shadows a shadowed light's batch is preceded by its map (ShadowedShading::hold) and
// drawn with the twin; the others keep the plain pipeline.
void LightPasses::record(PassContext& pc, const Targets& t, bool resolve) {
    std::vector<uint32_t> order;
    if (pipeline_)
        for (const LightBatch& batch : env_.plan.batches) order.push_back(batch.light);
    ShadowedShading shading(pc, t, resolve, env_.shadows, order, true);
    draws_ = 0;
    uint32_t tag = 0; // the stencil starts at 0 (cleared by each rendering's begin)
    if (pipeline_) {
        VkPipeline bound = pipeline_;
        bind(pc, pipeline_);
        for (const LightBatch& batch : env_.plan.batches) {
            const bool restarted = shading.hold(batch.light);
            const VkPipeline p = shading.shadowed(batch.light) ? shadowed_ : pipeline_;
            if (restarted || p != bound) {
                bind(pc, bound = p);
                if (p == shadowed_)
                    env_.shadows->bind(pc.cmd, env_.layout, VK_PIPELINE_BIND_POINT_GRAPHICS);
            }
            if (restarted) tag = 0;
            if (++tag > kMaxStencilTag) {
                clearStencil(pc, t);
                tag = 1;
            }
            vkCmdSetStencilReference(pc.cmd, VK_STENCIL_FACE_FRONT_AND_BACK, tag);
            setScissor(pc.cmd, batch.scissor);
            recordDraws(pc, batch);
        }
    }
    shading.end();
    mapRenders_ = shading.mapRenders();
}

// The scene set and index buffer the light's draws read: with GPU lists the meshlet index
// buffer (the commands are spans of meshlets), else drawOpaque's.
void LightPasses::bind(PassContext& pc, VkPipeline pipeline) const {
    if (litSet_)
        vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, env_.layout, TP_SET_PASS,
                                1, &litSet_, 0, nullptr);
    if (!env_.lightDraws) return bindSceneDraws(pc.cmd, env_, pipeline);
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    env_.scene.bindSceneSet(pc.cmd, env_.layout, VK_PIPELINE_BIND_POINT_GRAPHICS);
    env_.scene.bindMeshletIndexBuffer(pc.cmd);
}

void LightPasses::recordDraws(PassContext& pc, const LightBatch& batch) {
    if (!env_.lightDraws) {
        for (const DrawItem* d : batch.draws)
            drawOpaque(pc, env_, *d, batch.light);
        draws_ += uint32_t(batch.draws.size());
        return;
    }
    // The light in DrawPush (its materials come with the commands), then its runs' calls.
    const gpu::DrawPush push{0, batch.light, 0, 0};
    vkCmdPushConstants(pc.cmd, env_.layout, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
    draws_ += env_.lightDraws->record(pc, batch.slot);
}

} // namespace tp::mp
