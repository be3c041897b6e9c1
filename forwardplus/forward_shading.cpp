#include "forwardplus/forward_shading.h"

#include <string>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/rendering.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/lightassign/light_classes.h"
#include "core/passes/lights_ubo.h"
#include "core/passes/materials_ubo.h"
#include "core/passes/meshlet_cull.h"
#include "core/passes/shadow_maps.h"
#include "forwardplus/forwardplus_shared.h"

namespace tp::fp {

ForwardShading::~ForwardShading() {
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    destroyPassSet(ctx_, set_);
}

// Uses with a binding are also the pass's descriptor set (prepare); both passes declare the
// same bound uses and share one set.
std::vector<PassUse> ForwardShading::uses(bool transparent) const {
    const bool msaa = config_.sampling.msaa();
    std::vector<PassUse> uses = {{msaa ? t_.hdrMsaa : t_.hdr, Use::ColorAttachment},
                                 {msaa ? t_.depthMsaa : t_.depth, Use::DepthTest},
                                 {t_.tiles, Use::StorageRead, TP_FP_BINDING_TILES},
                                 {t_.indices, Use::StorageRead, TP_FP_BINDING_INDICES}};
    if (config_.clustered)
        uses.push_back({t_.masks, Use::StorageRead, TP_FP_BINDING_CLUSTER_MASKS});
    const bool lastPass = transparent || !config_.blendPass;
    if (msaa && lastPass) uses.push_back({t_.hdr, Use::ColorResolve});
    if (t_.shadows)
        for (const PassUse& u : t_.shadows->sampledUses()) uses.push_back(u);
    if (t_.cull && !transparent)
        for (const PassUse& u : t_.cull->drawUses()) uses.push_back(u);
    return uses;
}

void ForwardShading::plan(FrameGraph& graph, const ShadingTargets& t) {
    t_ = t;
    hdrClear_.plan(graph, "forward_hdr_clear", config_.sampling.msaa() ? t_.hdrMsaa : t_.hdr,
                   ColorTarget{}.clearValue);
    graph.addPass("forward_opaque", uses(false), [this](PassContext& pc) { record(pc, false); });
    if (config_.blendPass)
        graph.addPass("forward_transparent", uses(true),
                      [this](PassContext& pc) { record(pc, true); });
}

void ForwardShading::prepare(FrameGraph& graph, VkBuffer params) {
    hdrClear_.prepare(graph);
    createPassSet(graph, params);
    layout_ = scene_.createPipelineLayout(set_.layout, t_.shadows ? t_.shadows->setLayout() : VK_NULL_HANDLE);
    for (AlphaMode mode : {AlphaMode::Opaque, AlphaMode::Mask, AlphaMode::Blend})
        if (scene_.hasDraws(DrawFilter(mode))) pipelines_.create(scene_, mode, pipelineDesc(mode));
}

// The graph's set for the pass's uses and fp_params, plus the lights and the materials as
// uniform buffers (core/passes/lights_ubo.h, materials_ubo.h: read on a CPU device when they
// fit; docs/forwardplus.md, "The per-light cost on lavapipe"), the directional lights first in
// fp_params' order (ascending): the shader's loop takes the i-th directional light as slot i
// without loading its index (shading.frag).
void ForwardShading::createPassSet(FrameGraph& graph, VkBuffer params) {
    lightsUbo_.emplace(ctx_, scene_, "forwardplus", "fp_lights_ubo",
                       la::classifyLights(scene_.shadingLights()).directional);
    materialsUbo_.emplace(ctx_, scene_, "forwardplus", "fp_materials_ubo");
    set_ = graph.createPassSet("forward_opaque", VK_NULL_HANDLE,
                               {{TP_FP_BINDING_PARAMS, params},
                                {TP_FP_BINDING_LIGHTS_UBO, lightsUbo_->buffer(), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                {TP_FP_BINDING_MATERIALS_UBO, materialsUbo_->buffer(),
                                 VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}});
}

void ForwardShading::updateLights() {
    if (lightsUbo_) lightsUbo_->update();
}

GraphicsPipelineDesc ForwardShading::pipelineDesc(AlphaMode mode) const {
    GraphicsPipelineDesc d;
    // --msaa-shading: pixel runs once per pixel at its centre (no `sample` inputs, no
    // sample shading; the EQUAL depth test against the per-sample prepass gives each
    // sample its coverage, masked materials included); sample shades every sample.
    d.fragmentShader = std::string(config_.clustered ? "fp_shading_clustered" : "fp_shading") +
                       (config_.subgroupLoop ? "_subgroup" : "") +
                       (config_.sampling.perPixelUnderMsaa() ? "_pixel_frag" : "_frag");
    d.colorFormats = {t_.hdrFormat};
    d.samples = VkSampleCountFlagBits(config_.sampling.samples);
    d.sampleShading = config_.sampling.perSample();
    d.layout = layout_;
    d.passSet = &set_;
    d.depthWrite = false;
    d.depthCompare = mode == AlphaMode::Blend ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_EQUAL;
    d.blend = mode == AlphaMode::Blend ? BlendMode::Alpha : BlendMode::None;
    d.specConstants = scene_.specConstants(mode);
    d.specConstants.push_back({TP_SPEC_TILE_SIZE, config_.tileSize});
    d.specConstants.push_back({TP_FP_SPEC_TWO_LISTS, config_.twoLists ? 1u : 0u});
    d.specConstants.push_back({TP_FP_SPEC_LAYOUT, config_.layout});
    d.specConstants.push_back({TP_FP_SPEC_LIGHTS_UBO, lightsUbo_->active() ? 1u : 0u});
    d.specConstants.push_back({TP_FP_SPEC_MATERIALS_UBO, materialsUbo_->active() ? 1u : 0u});
    // The light count is fixed for a plan (a new view moves lights, never adds one).
    d.specConstants.push_back({TP_FP_SPEC_NO_LIGHTS, scene_.shadingLights().empty() ? 1u : 0u});
    // fp_params' directional count and tile grid, the same values as constants.
    const auto directional = la::classifyLights(scene_.shadingLights()).directional.size();
    d.specConstants.push_back({TP_FP_SPEC_DIRECTIONAL, uint32_t(directional)});
    d.specConstants.push_back({TP_FP_SPEC_TILES_X, config_.tilesX});
    d.specConstants.push_back({TP_FP_SPEC_TILES_Y, config_.tilesY});
    d.specConstants.push_back(
        {TP_FP_SPEC_HDR16, t_.hdrFormat == VK_FORMAT_R16G16B16A16_SFLOAT ? 1u : 0u});
    if (config_.clustered) {
        d.specConstants.push_back({TP_FP_SPEC_SLICES, config_.slices});
        d.specConstants.push_back({TP_FP_SPEC_BLENDED_SPAN, config_.blendPass ? 1u : 0u});
    }
    if (t_.shadows) t_.shadows->apply(d.fragmentShader, d.specConstants);
    return d;
}

void ForwardShading::record(PassContext& pc, bool transparent) {
    const bool msaa = config_.sampling.msaa();
    ColorTarget color;
    color.image = msaa ? t_.hdrMsaa : t_.hdr;
    const bool lastPass = transparent || !config_.blendPass;
    if (msaa && lastPass) color.resolve = t_.hdr;
    color.clear = !transparent && !hdrClear_.planned(); // else cleared by forward_hdr_clear
    DepthTarget depth{msaa ? t_.depthMsaa : t_.depth, {}, false, true};
    beginRendering(pc, {color}, depth);
    scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    if (t_.shadows) t_.shadows->bind(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
    std::vector<AlphaMode> modes = transparent
                                       ? std::vector<AlphaMode>{AlphaMode::Blend}
                                       : std::vector<AlphaMode>{AlphaMode::Opaque, AlphaMode::Mask};
    const bool culled = t_.cull && !transparent;
    if (culled)
        scene_.bindMeshletIndexBuffer(pc.cmd);
    else
        scene_.bindIndexBuffer(pc.cmd);
    for (AlphaMode mode : modes)
        pipelines_.forEachDraw(scene_, pc.cmd, mode, [&](const DrawItem& item) {
            if (culled)
                t_.cull->recordDraw(pc, layout_, item);
            else
                recordDraw(pc.cmd, layout_, item);
        });
    endRendering(pc);
}

} // namespace tp::fp
