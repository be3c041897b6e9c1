#include "core/passes/blended_forward.h"

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/rendering.h"
#include "core/gpu/resources.h"
#include "core/gpu/stand_ins.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/shadow_maps.h"
#include "passes/tiled_lighting.h"

namespace tp {

BlendedForwardPass::~BlendedForwardPass() {
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    destroyPassSet(ctx_, set_);
}

void BlendedForwardPass::plan(FrameGraph& graph, const BlendedForwardTargets& t, uint32_t slices,
                              ResourceHandle masks) {
    t_ = t;
    slices_ = masks.valid() ? slices : 0u;
    masks_ = masks;
    std::vector<PassUse> uses = {{t.lists, Use::StorageRead, TP_BF_BINDING_LISTS},
                                 {t.depth, Use::DepthTest},
                                 {t.bounds, Use::StorageRead, TP_BF_BINDING_BLEND_BOUNDS}};
    if (masks.valid()) uses.push_back({masks, Use::StorageRead, TP_BF_BINDING_MASKS});
    if (t.msaa()) {
        uses.push_back({t.hdrMsaa, Use::ColorAttachment});
        uses.push_back({t.hdr, Use::ColorResolve});
    } else {
        uses.push_back({t.hdr, Use::ColorAttachment});
    }
    if (t.shadows)
        for (const PassUse& u : t.shadows->sampledUses()) uses.push_back(u);
    graph.addPass("transparent_forward", uses, [this](PassContext& pc) { record(pc); });
}

bool BlendedForwardPass::shadowed() const { return t_.shadows && t_.shadows->enabled(); }

void BlendedForwardPass::prepare(FrameGraph& graph, bool binned, const LightsUbo& lights) {
    materialsUbo_.emplace(ctx_, scene_, graph.owner(), "transparent_forward_materials_ubo");
    std::vector<ExternalBuffer> externals{
        {TP_BF_BINDING_LIGHTS_UBO, lights.buffer(), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
        {TP_BF_BINDING_MATERIALS_UBO, materialsUbo_->buffer(), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}};
    if (!masks_.valid()) {
        noMasks_ = createStandInBuffer(ctx_, {graph.owner(), "", "transparent_cluster_masks_unused",
                                              "stand-in: slice rows are clustered only"});
        externals.push_back({TP_BF_BINDING_MASKS, noMasks_.buffer});
    }
    set_ = graph.createPassSet("transparent_forward", VK_NULL_HANDLE, externals);
    layout_ = scene_.createPipelineLayout(set_.layout,
                                          shadowed() ? t_.shadows->setLayout() : VK_NULL_HANDLE);
    GraphicsPipelineDesc d;
    // --msaa-shading pixel under MSAA: inputs at the pixel centre (scene_inputs.glsl), no
    // sample shading; each covered sample that passes the depth test blends the pixel's value.
    d.fragmentShader =
        t_.perPixel ? "blended_forward_pixel_frag" : "blended_forward_frag";
    d.specConstants = scene_.specConstants(AlphaMode::Blend);
    d.specConstants.push_back({TP_SPEC_TILE_SIZE, t_.grid.tileSize});
    d.specConstants.push_back({TP_TL_SPEC_SLICES, slices_});
    d.specConstants.push_back({TP_TL_SPEC_BINNED, binned ? 1u : 0u}); // the ambient term last
    d.specConstants.push_back({TP_TL_SPEC_LIGHTS_UBO, lights.active() ? 1u : 0u});
    d.specConstants.push_back({TP_BF_SPEC_MATERIALS_UBO, materialsUbo_->active() ? 1u : 0u});
    if (shadowed()) t_.shadows->apply(d.fragmentShader, d.specConstants); // the _shadow twin
    d.colorFormats = {t_.hdrFormat};
    d.samples = VkSampleCountFlagBits(t_.samples);
    d.sampleShading =
        t_.msaa() && !t_.perPixel; // --msaa-shading sample: every sample, as the reference
    d.depthWrite = false;
    d.blend = BlendMode::Alpha;
    d.layout = layout_;
    d.passSet = &set_;
    pipelines_.create(scene_, AlphaMode::Blend, d);
}

void BlendedForwardPass::record(PassContext& pc) {
    ColorTarget color =
        t_.msaa() ? ColorTarget{t_.hdrMsaa, t_.hdr, false} : ColorTarget{t_.hdr, {}, false};
    DepthTarget depth{t_.depth, {}, false, true};
    beginRendering(pc, {color}, depth);
    scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    if (shadowed()) t_.shadows->bind(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
    scene_.bindIndexBuffer(pc.cmd);
    pipelines_.forEachDraw(scene_, pc.cmd, AlphaMode::Blend,
                           [&](const DrawItem& item) { recordDraw(pc.cmd, layout_, item); });
    endRendering(pc);
}

} // namespace tp
