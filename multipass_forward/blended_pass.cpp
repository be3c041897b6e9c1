// Blended surfaces, back to front, one draw at a time (the reference's order):
//   1. composite: ambient + emissive + directional lights, alpha-blended over what is behind,
//      triangles in the scene's order (as the reference);
//   2. per light touching the draw: the draw's triangles in REVERSE order, each adding
//      T * alpha * light, where T, the target's alpha, starts at 1 and is multiplied by
//      (1 - alpha) at each layer ("under" compositing, front to back in drawing order);
//      then an alpha-only draw puts T back to 1.
// Compositing under in reverse order equals compositing over in order, so each light of a
// draw that overlaps itself (cloth folds, several panels in one mesh) is attenuated by the
// layers drawn after it exactly as in the reference's single shade-and-blend. Simply adding
// alpha * light instead (the textbook multipass) overcounts by a_near * a_far * L_far per
// self-overlap (docs/multipass_forward.md: 48.9 dB instead of 157 dB on the courtyard);
// --blended-lights additive keeps that textbook pass, to measure the difference;
// --blended-lights one-pass draws only the composite, with every light in it
// (one_pass.frag), as engines light transparent objects.
// With GPU lists (--light-draws gpu, blended_light_draw_pass.h) step 2 is one indirect call per
// draw: the GPU wrote the light draws and resets, and one dual-source pipeline draws both.
#include "core/gpu/context.h"
#include "core/gpu/rendering.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/shadow_maps.h"
#include "core/renderer/renderer.h"
#include "multipass_forward/blended_light_draw_pass.h"
#include "multipass_forward/blended_light_draws.h"
#include "multipass_forward/passes.h"

namespace tp::mp {

std::vector<SpecConstant> directionalSpec(const LightPlan& plan); // base_pass.cpp

namespace {

// Colour += src * T (T = dst alpha); T *= 1 - src alpha.
VkPipelineColorBlendAttachmentState underBlend() {
    VkPipelineColorBlendAttachmentState a{};
    a.blendEnable = VK_TRUE;
    a.srcColorBlendFactor = VK_BLEND_FACTOR_DST_ALPHA;
    a.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
    a.colorBlendOp = VK_BLEND_OP_ADD;
    a.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
    a.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    a.alphaBlendOp = VK_BLEND_OP_ADD;
    a.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                       VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    return a;
}

// One blend state for a light draw and its reset (light.frag, TP_MP_BLENDED_GPU): colour
// src0 * T + dst as underBlend(); alpha src0.a + T * (1 - src1.a), with src0.a = 0 for a light
// draw (T * (1 - alpha), as underBlend's 0 + T * (1 - alpha)) and src0.a = src1.a = 1 for a reset
// (1 + T * 0 = 1, as alphaOnly's 1).
VkPipelineColorBlendAttachmentState dualSourceUnderBlend() {
    VkPipelineColorBlendAttachmentState a = underBlend();
    a.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    a.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC1_ALPHA;
    return a;
}

VkPipelineColorBlendAttachmentState alphaOnly() {
    VkPipelineColorBlendAttachmentState a{};
    a.colorWriteMask = VK_COLOR_COMPONENT_A_BIT;
    return a;
}

} // namespace

BlendedPass::BlendedPass(const PassEnv& env)
    : env_(env), additive_(env.settings.blendedLights == BlendedLights::Additive),
      onePass_(env.settings.blendedLights == BlendedLights::OnePass) {
    if (!env.allDraws && env.plan.blended.empty()) return;
    // Depth GREATER against the opaque depth, no writes: as the reference draws them.
    GraphicsPipelineDesc d = shadingDesc(env, AlphaMode::Blend);
    d.depthWrite = false;
    GraphicsPipelineDesc base = d;
    for (SpecConstant c : directionalSpec(env.plan))
        base.specConstants.push_back(c);
    base.fragmentShader = fragmentShader(env, onePass_ ? "one_pass" : "base");
    base.blend = BlendMode::Alpha;
    base_ = createGraphicsPipeline(env.ctx, base);
    if (onePass_) return; // the composite is everything (the plan gave blended draws no lights)
    d.fragmentShader = fragmentShader(env, "light");
    if (additive_) { // --blended-lights additive: alpha * light added, no transmittance
        d.blend = BlendMode::Additive;
        light_ = createGraphicsPipeline(env.ctx, d);
        lightShadowed_ = createShadowedTwin(env, d);
        return;
    }
    d.blend = BlendMode::Custom;
    if (env.blendedLightDraws) {
        createGpuLightPipeline(d);
        return;
    }
    d.customBlend = underBlend();
    light_ = createGraphicsPipeline(env.ctx, d);
    lightShadowed_ = createShadowedTwin(env, d);
    d.fragmentShader = "mp_alpha_reset_frag";
    d.customBlend = alphaOnly();
    d.sampleShading = false; // a constant: per-sample coverage is enough
    reset_ = createGraphicsPipeline(env.ctx, d);
    createReversedIndices();
}

// GPU lists: the light draws and resets of every blended draw of the scene (the plan no longer
// says which are lit), read from the GPU's commands with each light's slot in firstInstance.
void BlendedPass::createGpuLightPipeline(GraphicsPipelineDesc d) {
    PassSet lightSet; // what the shader's set TP_SET_PASS is checked against (reflection)
    lightSet.pass = "blended";
    lightSet.bindings = {{TP_MPBL_BINDING_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
    lightSet.layout = env_.blendedLightDraws->lightSetLayout();
    d.vertexShader = "scene_material_vert";
    d.fragmentShader = fragmentShader(env_, "light_blend");
    d.customBlend = dualSourceUnderBlend();
    d.passSet = &lightSet;
    lightGpu_ = createGraphicsPipeline(env_.ctx, d);
    createReversedIndices();
}

BlendedPass::~BlendedPass() {
    destroyPipeline(env_.ctx, lightGpu_);
    destroyPipeline(env_.ctx, base_);
    destroyPipeline(env_.ctx, light_);
    destroyPipeline(env_.ctx, lightShadowed_);
    destroyPipeline(env_.ctx, reset_);
}

// The triangles of every blended draw that has lights, in reverse order (each triangle's
// own vertex order kept, so facing is unchanged), in one index buffer of this pipeline. With
// allDraws every blended draw of the scene, so no view needs a new buffer.
void BlendedPass::createReversedIndices() {
    std::vector<const DrawItem*> lit;
    if (env_.allDraws || env_.blendedLightDraws)
        lit = env_.scene.drawList(DrawFilter::Blend);
    else
        for (const BlendedDraw& bd : env_.plan.blended)
            if (!bd.lights.empty()) lit.push_back(bd.draw);
    std::vector<uint32_t> reversed;
    reversedFirst_.clear();
    for (const DrawItem* draw : lit) {
        // The scene's index buffer is its meshes' indices in order (SceneGpu::uploadGeometry).
        uint32_t first = 0;
        const Mesh* mesh = nullptr;
        for (const Mesh& m : env_.scene.scene().meshes) {
            if (first == draw->firstIndex && uint32_t(m.indices.size()) == draw->indexCount) {
                mesh = &m;
                break;
            }
            first += uint32_t(m.indices.size());
        }
        if (!mesh) throw RendererError("multipass_forward: a blended draw matches no mesh");
        reversedFirst_[draw] = uint32_t(reversed.size());
        for (size_t t = mesh->indices.size(); t >= 3; t -= 3)
            reversed.insert(reversed.end(), mesh->indices.begin() + ptrdiff_t(t - 3),
                            mesh->indices.begin() + ptrdiff_t(t));
    }
    reversedIndices_ = {};
    if (reversed.empty()) return;
    reversedIndices_ =
        createBufferWithData(env_.ctx, reversed.data(), reversed.size() * sizeof(uint32_t),
                             VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                             {"multipass_forward", "blended", "blended_indices_reversed",
                              "lit blended meshes' triangles in reverse order (light passes)"});
}

void BlendedPass::follow() {
    if (!light_ || additive_ || onePass_) return; // also GPU lists: every draw has its range
    for (const BlendedDraw& bd : env_.plan.blended)
        if (!bd.lights.empty() && !reversedFirst_.count(bd.draw)) {
            createReversedIndices();
            return;
        }
}

// --shadows: a shadowed light's map, unless the map holds it already (the previous draw's
// last light), and the twin. A new rendering has lost the bindings (the map's own replaced
// them): the scene set, the shadow set and `indices` again. Without shadows: light_.
void BlendedPass::bindLight(PassContext& pc, ShadowedShading& shading, uint32_t light,
                            VkBuffer indices) {
    if (shading.hold(light)) {
        env_.scene.bindSceneSet(pc.cmd, env_.layout, VK_PIPELINE_BIND_POINT_GRAPHICS);
        env_.shadows->bind(pc.cmd, env_.layout, VK_PIPELINE_BIND_POINT_GRAPHICS);
        vkCmdBindIndexBuffer(pc.cmd, indices, 0, VK_INDEX_TYPE_UINT32);
        bound_ = VK_NULL_HANDLE;
    }
    const VkPipeline p = shading.shadowed(light) ? lightShadowed_ : light_;
    if (p != bound_) vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound_ = p);
}

// The exact light passes: each light's triangles of the draw in reverse order, composited
// under the layers already passed (transmittance in the target's alpha), then T reset to 1.
void BlendedPass::recordUnderLights(PassContext& pc, const BlendedDraw& bd, ShadowedShading& shading) {
    if (bd.lights.empty()) return;
    vkCmdBindIndexBuffer(pc.cmd, reversedIndices_.buffer, 0, VK_INDEX_TYPE_UINT32);
    DrawItem reversed = *bd.draw;
    reversed.firstIndex = reversedFirst_.at(bd.draw);
    for (const auto& [light, scissor] : bd.lights) {
        bound_ = VK_NULL_HANDLE; // the reset's pipeline was bound last: light_ again, as before
        bindLight(pc, shading, light, reversedIndices_.buffer);
        setScissor(pc.cmd, scissor);
        recordDraw(pc.cmd, env_.layout, reversed, light);
        // The reset reads no push constant and keeps the light draw's cull mode (dynamic state
        // and push constants outlive a bind of a pipeline of the same layout): the draw alone,
        // two commands fewer per blended light to record at each view.
        vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, reset_);
        vkCmdDrawIndexed(pc.cmd, reversed.indexCount, 1, reversed.firstIndex, reversed.vertexOffset,
                         0);
    }
}

// The textbook blended light pass (--blended-lights additive): each light adds alpha * light
// of every layer, in the scene's triangle order, so a far layer's share lands after the near
// layer of the same draw was blended over it and escapes its (1 - alpha). Kept to measure
// what the exact passes buy (docs/multipass_forward.md).
void BlendedPass::recordAdditiveLights(PassContext& pc, const BlendedDraw& bd,
                                       ShadowedShading& shading) {
    if (bd.lights.empty()) return;
    bound_ = VK_NULL_HANDLE; // the composite's pipeline is bound
    for (const auto& [light, scissor] : bd.lights) {
        bindLight(pc, shading, light, env_.scene.indexBuffer());
        setScissor(pc.cmd, scissor);
        recordDraw(pc.cmd, env_.layout, *bd.draw, light);
    }
}

// GPU lists: the composite's push constant (the draw's material) and cull mode hold for the
// light draws and resets (same layout); the GPU's commands name the light and the reset.
void BlendedPass::recordGpuLights(PassContext& pc, uint32_t b) {
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, lightGpu_);
    vkCmdBindIndexBuffer(pc.cmd, reversedIndices_.buffer, 0, VK_INDEX_TYPE_UINT32);
    env_.blendedLightDraws->record(pc, b);
}

void BlendedPass::record(PassContext& pc, const Targets& t, bool resolve) {
    std::vector<uint32_t> order; // the lights in the order their passes run
    if (light_)
        for (const BlendedDraw& bd : env_.plan.blended)
            for (const auto& lightRect : bd.lights) order.push_back(lightRect.first);
    ShadowedShading shading(pc, t, resolve, env_.shadows, order);
    const SceneGpu& scene = env_.scene;
    scene.bindSceneSet(pc.cmd, env_.layout, VK_PIPELINE_BIND_POINT_GRAPHICS);
    const ScreenRect full{0, 0, int32_t(env_.settings.width), int32_t(env_.settings.height)};
    draws_ = lightDraws_ = 0;
    if (lightGpu_) env_.blendedLightDraws->bindLightSet(pc.cmd, env_.layout);
    for (size_t b = 0; b < env_.plan.blended.size(); ++b) {
        const BlendedDraw& bd = env_.plan.blended[b];
        vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, base_);
        scene.bindIndexBuffer(pc.cmd);
        setScissor(pc.cmd, full);
        recordDraw(pc.cmd, env_.layout, *bd.draw);
        if (lightGpu_)
            recordGpuLights(pc, uint32_t(b));
        else if (additive_)
            recordAdditiveLights(pc, bd, shading);
        else
            recordUnderLights(pc, bd, shading);
        // A composite, then per light one draw (additive) or a light draw and a reset (under).
        draws_ += 1 + (additive_ ? 1u : 2u) * uint32_t(bd.lights.size());
        lightDraws_ += uint32_t(bd.lights.size());
    }
    shading.end();
    mapRenders_ = shading.mapRenders();
}

} // namespace tp::mp
