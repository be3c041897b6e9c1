#include "deferred/volume_lighting.h"

#include <algorithm>
#include <bit>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/rendering.h"
#include "core/gpu/stand_ins.h"
#include "core/gpu/vk_check.h"
#include "core/gpuscene/scene_gpu.h"

namespace tp {

float circumscribedSphereScale() {
    float nearest = 1.0f;
    for (uint32_t k = 0; k < TP_DEF_SPHERE_VERTICES; k += 3) {
        glm::vec3 a = gpu::volumeSphereVertex(k), b = gpu::volumeSphereVertex(k + 1),
                  c = gpu::volumeSphereVertex(k + 2);
        glm::vec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) < 1e-6f) continue; // the degenerate half of a polar quad
        nearest = std::min(nearest, std::abs(glm::dot(glm::normalize(n), a)));
    }
    return 1.001f / nearest;
}

bool drawsCone(const gpu::LightGpu& light) {
    return light.type == TP_LIGHT_SPOT && -light.spotOffset / light.spotScale >= 0.5f;
}

VolumeLighting::~VolumeLighting() {
    for (Stage* s : {&base_, &lights_, &sampleBase_, &shadowed_}) {
        if (s->pipeline) vkDestroyPipeline(ctx_.device, s->pipeline, nullptr);
        if (s->layout) vkDestroyPipelineLayout(ctx_.device, s->layout, nullptr);
        destroyPassSet(ctx_, s->set);
    }
    if (sampler_) vkDestroySampler(ctx_.device, sampler_, nullptr);
}

void VolumeLighting::plan(FrameGraph& graph, DeferredTargets& t) {
    t_ = &t;
    const bool msaa = t.msaa();
    if (msaa) {
        // RGBA8 rather than R8 so the statistics and --debug can read it back.
        t.edgeMask = graph.createImage("volume_edge_mask",
                                       {VK_FORMAT_R8G8B8A8_UNORM, 0, 0, VK_SAMPLE_COUNT_1_BIT,
                                        "edge mask: pixels shaded per sample"});
        t.volumeDepth = graph.createImage(
            "volume_depth", {VK_FORMAT_D32_SFLOAT, 0, 0, VK_SAMPLE_COUNT_1_BIT,
                             "nearest sample depth (1 on edges): volumes' depth test"});
    }
    // Each resource once, with the binding (set TP_SET_PASS) the shaders read it at.
    const uint32_t numbers[] = {TP_DEF_BINDING_BASE, TP_DEF_BINDING_NORMAL,
                                TP_DEF_BINDING_ROUGH_METAL, TP_DEF_BINDING_EMISSIVE};
    std::vector<PassUse> gbuffer, lights;
    for (size_t i = 0; i < t.gbuffer.size(); ++i)
        gbuffer.push_back({t.gbuffer[i], Use::Sampled, numbers[i]});
    gbuffer.push_back({t.gbufferDepth, Use::Sampled, TP_TL_BINDING_DEPTH});
    for (size_t i = 0; i < 3; ++i)
        lights.push_back({t.gbuffer[i], Use::Sampled, numbers[i]}); // no emissive
    std::vector<PassUse> base = gbuffer, sampleBase = gbuffer;
    base.push_back({t.hdr, Use::ColorAttachment});
    if (perSampleHdr()) {
        // Lit per sample into hdr_msaa, with no depth test (volume_light.frag says why).
        sampleBase.push_back({t.hdrMsaa, Use::ColorAttachment});
        sampleBase.push_back({t.edgeMask, Use::Sampled, TP_DEF_BINDING_EDGE_MASK});
        lights.push_back({t.hdrMsaa, Use::ColorAttachment});
        lights.push_back({t.gbufferDepth, Use::Sampled, TP_TL_BINDING_DEPTH});
        lights.push_back({t.edgeMask, Use::Sampled, TP_DEF_BINDING_EDGE_MASK});
    } else {
        lights.push_back({t.hdr, Use::ColorAttachment});
        if (msaa) {
            lights.push_back({t.gbufferDepth, Use::Sampled, TP_TL_BINDING_DEPTH});
            lights.push_back({t.volumeDepth, Use::DepthTest});
            lights.push_back({t.edgeMask, Use::Sampled, TP_DEF_BINDING_EDGE_MASK});
        } else {
            lights.push_back(
                {t.gbufferDepth, Use::DepthTest, TP_TL_BINDING_DEPTH}); // tested and sampled
        }
    }
    if (msaa) {
        base.push_back({t.edgeMask, Use::ColorAttachment});
        base.push_back({t.volumeDepth, Use::DepthAttachment});
    }
    graph.addPass("volume_base", base, [this](PassContext& pc) { recordBase(pc); });
    if (perSampleHdr())
        graph.addPass("volume_sample_base", sampleBase,
                      [this](PassContext& pc) { recordSampleBase(pc); });
    graph.addPass("volume_lights", lights, [this](PassContext& pc) { recordLights(pc); });
    // --shadows: the shadowed lights, each right after its map is rendered into the one map
    // (its depth attachment, rendered over for every light). A pass of its own, so that its
    // time (the map renders and these volumes) is apart from the unshadowed lights'. Nothing
    // new is declared without shadows.
    if (shadows_.plan(graph).valid()) {
        for (const PassUse& u : shadows_.perLightUses()) lights.push_back(u); // map, culled draws
        graph.addPass("volume_shadowed_lights", lights,
                      [this](PassContext& pc) { recordShadowedLights(pc); });
    }
}

void VolumeLighting::prepare(FrameGraph& graph) {
    // texelFetch only: the sampler's filtering is never used.
    sampler_ = createNearestClampSampler(ctx_);
    prepareBase(graph);
    prepareLights(graph);
    if (perSampleHdr()) prepareSampleBase(graph);
    if (shadowPass()) {
        shadows_.prepare(graph);
        shadowed_.set = graph.createPassSet("volume_shadowed_lights", sampler_);
        shadowed_.layout = scene_.createPipelineLayout(shadowed_.set.layout, shadows_.setLayout());
        GraphicsPipelineDesc d = lightsDesc(shadowed_);
        shadows_.apply(d.fragmentShader, d.specConstants); // the _shadow twin, local rects
        shadowed_.pipeline = createGraphicsPipeline(ctx_, d);
    }
}

void VolumeLighting::prepareBase(FrameGraph& graph) {
    base_.set = graph.createPassSet("volume_base", sampler_);
    base_.layout = scene_.createPipelineLayout(base_.set.layout);
    GraphicsPipelineDesc d;
    d.vertexShader = "deferred_fullscreen_vert";
    d.fragmentShader = std::string("deferred_volume_base_m") + (t_->msaa() ? "1" : "0") + "_e" +
                       (t_->layout.emissive ? "1" : "0") + "_frag";
    d.specConstants = scene_.specConstants(AlphaMode::Opaque);
    d.specConstants.push_back({TP_DEF_SPEC_WIDE, t_->layout.wide ? 1u : 0u});
    d.specConstants.push_back({TP_SPEC_SAMPLES, t_->layout.samples});
    d.specConstants.push_back({TP_TL_SPEC_EVERY_SAMPLE, t_->sampleRateGBuffer ? 1u : 0u});
    d.colorFormats = {t_->hdrFormat};
    d.depthFormat = VK_FORMAT_UNDEFINED;
    d.depthTest = d.depthWrite = false;
    if (t_->msaa()) {
        d.colorFormats.push_back(VK_FORMAT_R8G8B8A8_UNORM);
        d.depthFormat = VK_FORMAT_D32_SFLOAT;
        d.depthTest = d.depthWrite = true; // writes need the test on; ALWAYS passes
        d.depthCompare = VK_COMPARE_OP_ALWAYS;
    }
    d.layout = base_.layout;
    d.passSet = &base_.set;
    base_.pipeline = createGraphicsPipeline(ctx_, d);
}

void VolumeLighting::prepareLights(FrameGraph& graph) {
    lights_.set = graph.createPassSet("volume_lights", sampler_);
    lights_.layout = scene_.createPipelineLayout(lights_.set.layout);
    lights_.pipeline = createGraphicsPipeline(ctx_, lightsDesc(lights_));
}

GraphicsPipelineDesc VolumeLighting::lightsDesc(const Stage& stage) const {
    GraphicsPipelineDesc d;
    d.vertexShader = "deferred_volume_vert";
    d.fragmentShader = std::string("deferred_volume_light_m") +
                       (perSampleHdr() ? "2"
                        : t_->msaa()   ? "1"
                                       : "0") +
                       "_frag";
    d.specConstants = scene_.specConstants(AlphaMode::Opaque);
    d.specConstants.push_back({TP_DEF_SPEC_WIDE, t_->layout.wide ? 1u : 0u});
    d.specConstants.push_back({TP_SPEC_SAMPLES, t_->layout.samples});
    d.specConstants.push_back(
        {TP_DEF_SPEC_SPHERE_SCALE, std::bit_cast<uint32_t>(circumscribedSphereScale())});
    d.colorFormats = {t_->hdrFormat};
    d.depthWrite = false;
    d.depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL; // reverse-Z: back face at or behind the surface
    d.blend = BlendMode::Additive;
    d.layout = stage.layout;
    d.passSet = &stage.set;
    if (perSampleHdr()) {
        d.samples = VkSampleCountFlagBits(t_->layout.samples);
        d.sampleShading = true;
        d.depthFormat = VK_FORMAT_UNDEFINED;
        d.depthTest = false;
    }
    return d;
}

void VolumeLighting::prepareSampleBase(FrameGraph& graph) {
    sampleBase_.set = graph.createPassSet("volume_sample_base", sampler_);
    sampleBase_.layout = scene_.createPipelineLayout(sampleBase_.set.layout);
    GraphicsPipelineDesc d;
    d.vertexShader = "deferred_fullscreen_vert";
    d.fragmentShader =
        std::string("deferred_volume_sample_base_e") + (t_->layout.emissive ? "1" : "0") + "_frag";
    d.specConstants = scene_.specConstants(AlphaMode::Opaque);
    d.specConstants.push_back({TP_DEF_SPEC_WIDE, t_->layout.wide ? 1u : 0u});
    d.specConstants.push_back({TP_SPEC_SAMPLES, t_->layout.samples});
    d.colorFormats = {t_->hdrFormat};
    d.samples = VkSampleCountFlagBits(t_->layout.samples);
    d.sampleShading = true;
    d.depthFormat = VK_FORMAT_UNDEFINED;
    d.depthTest = d.depthWrite = false;
    d.layout = sampleBase_.layout;
    d.passSet = &sampleBase_.set;
    sampleBase_.pipeline = createGraphicsPipeline(ctx_, d);
}

void VolumeLighting::bind(VkCommandBuffer cmd, const Stage& stage) {
    scene_.bindSceneSet(cmd, stage.layout, VK_PIPELINE_BIND_POINT_GRAPHICS);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, stage.layout, TP_SET_PASS, 1,
                            &stage.set.set, 0, nullptr);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, stage.pipeline);
}

void VolumeLighting::recordBase(PassContext& pc) {
    std::vector<ColorTarget> colors = {{t_->hdr}};
    std::optional<DepthTarget> depth;
    if (t_->msaa()) {
        colors.push_back({t_->edgeMask});
        depth = DepthTarget{t_->volumeDepth};
    }
    beginRendering(pc, colors, depth);
    bind(pc.cmd, base_);
    vkCmdSetCullMode(pc.cmd, VK_CULL_MODE_NONE);
    vkCmdDraw(pc.cmd, 3, 1, 0, 0);
    endRendering(pc);
}

void VolumeLighting::beginLights(PassContext& pc) {
    if (perSampleHdr()) {
        beginRendering(pc, {ColorTarget{t_->hdrMsaa, {}, false}}, std::nullopt);
    } else {
        ResourceHandle depth = t_->msaa() ? t_->volumeDepth : t_->gbufferDepth;
        beginRendering(pc, {ColorTarget{t_->hdr, {}, false}}, DepthTarget{depth, {}, false, true});
    }
}

void VolumeLighting::drawVolume(VkCommandBuffer cmd, uint32_t light) {
    const gpu::LightGpu& l = scene_.lightsGpu()[light];
    const bool cone = drawsCone(l);
    uint32_t vertices = l.type == TP_LIGHT_DIRECTIONAL ? 3u
                        : cone                         ? TP_DEF_CONE_VERTICES
                                                       : TP_DEF_SPHERE_VERTICES;
    vkCmdDraw(cmd, vertices, 1, 0, 2 * light + (cone ? 1u : 0u)); // firstInstance: light, mesh
}

// Every light without a shadow (all of them without --shadows), in one rendering.
void VolumeLighting::recordLights(PassContext& pc) {
    beginLights(pc);
    bind(pc.cmd, lights_);
    vkCmdSetCullMode(pc.cmd, VK_CULL_MODE_FRONT_BIT); // back faces only
    for (uint32_t i = 0; i < scene_.lightCount(); ++i)
        if (!shadows_.shadowed(i)) drawVolume(pc.cmd, i);
    endRendering(pc);
}

// Each shadowed light: its map rendered into the one map (no rendering open), then its volume
// in a rendering of its own that samples it, then the map back to an attachment for the next.
void VolumeLighting::recordShadowedLights(PassContext& pc) {
    bool first = true;
    for (uint32_t i = 0; i < scene_.lightCount(); ++i) {
        if (!shadows_.shadowed(i)) continue;
        shadows_.recordLight(pc, i);
        // The previous light's blend into the same target, outside this rendering: the graph
        // orders passes, not the renderings inside one, so the hazard is ours to cover.
        if (!first)
            memoryBarrier(pc.cmd, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                          VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                          VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        first = false;
        beginLights(pc);
        bind(pc.cmd, shadowed_); // recordLight bound its own pipeline and sets
        shadows_.bind(pc.cmd, shadowed_.layout, VK_PIPELINE_BIND_POINT_GRAPHICS);
        vkCmdSetCullMode(pc.cmd, VK_CULL_MODE_FRONT_BIT);
        drawVolume(pc.cmd, i);
        endRendering(pc);
        shadows_.endLight(pc);
    }
}

void VolumeLighting::recordSampleBase(PassContext& pc) {
    beginRendering(pc, {ColorTarget{t_->hdrMsaa}}, std::nullopt);
    bind(pc.cmd, sampleBase_);
    vkCmdSetCullMode(pc.cmd, VK_CULL_MODE_NONE);
    vkCmdDraw(pc.cmd, 3, 1, 0, 0);
    endRendering(pc);
}

} // namespace tp
