#include "visbuffer/raster_merge_pass.h"

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/rendering.h"
#include "core/gpu/resources.h"
#include "core/gpuscene/scene_gpu.h"
#include "visbuffer/vis_raster.h"

namespace tp::vis {

RasterMergePass::~RasterMergePass() {
    for (VkPipeline p : {seedPipeline_, listed_, merge_})
        if (p) vkDestroyPipeline(ctx_.device, p, nullptr);
    for (VkPipelineLayout l : {seedLayout_, listedLayout_, mergeLayout_})
        if (l) vkDestroyPipelineLayout(ctx_.device, l, nullptr);
    for (PassSet* set : {&seedSet_, &listedSet_, &mergeSet_})
        destroyPassSet(ctx_, *set);
}

bool RasterMergePass::planSeed(FrameGraph& graph, uint32_t samples,
                               const VisibilityTargets& targets, const RasterTargets& raster) {
    if (samples > 1) return false;
    t_ = targets;
    raster_ = raster;
    seed_ = graph.createBuffer("vis_raster_seed", VkDeviceSize(graph.width()) * graph.height() * 4,
                               "1x: the compute rasterizer's depths, copied into the depth image");
    graph.addPass("vis_raster_seed",
                  {{raster.samples, Use::StorageRead, TP_VR_BINDING_SEED_SAMPLES},
                   {seed_, Use::StorageWrite, TP_VR_BINDING_SEED},
                   {t_.ids, Use::StorageWrite, TP_VR_BINDING_SEED_IDS}},
                  [this](PassContext& pc) { recordSeed(pc); });
    graph.addPass("vis_raster_seed_copy", {{seed_, Use::TransferSrc}, {t_.depth, Use::TransferDst}},
                  [this](PassContext& pc) { recordSeedCopy(pc); });
    return true;
}

void RasterMergePass::plan(FrameGraph& graph, uint32_t samples, const VisibilityTargets& targets,
                           ResourceHandle resolvedDepth, const RasterTargets& raster) {
    samples_ = samples;
    t_ = targets;
    resolved_ = resolvedDepth;
    raster_ = raster;
    if (raster.hybrid)
        graph.addPass("vis_raster_hw",
                      {{t_.ids, Use::ColorAttachment},
                       {t_.depth, Use::DepthAttachment},
                       {raster.hwList, Use::StorageRead, TP_VR_BINDING_VIS_LIST},
                       {raster.args, Use::IndirectRead}},
                      [this](PassContext& pc) { recordListed(pc); });
    if (samples == 1) return; // seeded (planSeed)
    std::vector<PassUse> uses{{t_.ids, Use::ColorAttachment},
                              {t_.depth, Use::DepthAttachment},
                              {raster.samples, Use::StorageRead, TP_VR_BINDING_VIS_SAMPLES}};
    if (samples > 1) uses.push_back({resolvedDepth, Use::DepthResolve});
    graph.addPass("vis_raster_merge", uses, [this](PassContext& pc) { recordMerge(pc); });
}

// Neither draw is culled by the hardware: vis_raster culled back faces per draw already.
void RasterMergePass::prepare(FrameGraph& graph) {
    GraphicsPipelineDesc d;
    d.colorFormats = {VK_FORMAT_R32_SFLOAT};
    d.samples = VkSampleCountFlagBits(samples_);
    if (raster_.hybrid) {
        listedSet_ = graph.createPassSet("vis_raster_hw");
        listedLayout_ = scene_.createPipelineLayout(listedSet_.layout);
        d.layout = listedLayout_;
        d.passSet = &listedSet_;
        d.vertexShader = "vis_raster_hw_vert";
        d.fragmentShader = "vis_raster_hw_frag";
        d.specConstants = scene_.specConstants(AlphaMode::Opaque);
        listed_ = createGraphicsPipeline(ctx_, d);
    }
    if (seed_.valid()) {
        seedSet_ = graph.createPassSet("vis_raster_seed");
        seedLayout_ = scene_.createPipelineLayout(seedSet_.layout);
        seedPipeline_ = createComputePipeline(ctx_, "vis_raster_seed_comp", {}, seedLayout_,
                                              &seedSet_);
        return;
    }
    mergeSet_ = graph.createPassSet("vis_raster_merge");
    mergeLayout_ = scene_.createPipelineLayout(mergeSet_.layout);
    d.layout = mergeLayout_;
    d.passSet = &mergeSet_;
    d.vertexShader = "vis_raster_merge_vert";
    d.fragmentShader = "vis_raster_merge_frag";
    d.sampleShading = samples_ > 1; // one invocation per sample: each its own (depth, id)
    d.specConstants = scene_.specConstants(AlphaMode::Opaque);
    d.specConstants.push_back({TP_SPEC_SAMPLES, samples_});
    merge_ = createGraphicsPipeline(ctx_, d);
}

// The scene set, the pass's set, zero push constants, no face culling and the pipeline: what
// both of this file's draws need before they draw.
void RasterMergePass::bind(PassContext& pc, VkPipelineLayout layout, const PassSet& set,
                           VkPipeline pipeline) {
    scene_.bindSceneSet(pc.cmd, layout, VK_PIPELINE_BIND_POINT_GRAPHICS);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, TP_SET_PASS, 1,
                            &set.set, 0, nullptr);
    const gpu::DrawPush push{};
    vkCmdPushConstants(pc.cmd, layout, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
    vkCmdSetCullMode(pc.cmd, VK_CULL_MODE_NONE);
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
}

void RasterMergePass::recordSeed(PassContext& pc) {
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, seedPipeline_);
    scene_.bindSceneSet(pc.cmd, seedLayout_, VK_PIPELINE_BIND_POINT_COMPUTE);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, seedLayout_, TP_SET_PASS, 1,
                            &seedSet_.set, 0, nullptr);
    vkCmdDispatch(pc.cmd, (pc.graph.width() + 7) / 8, (pc.graph.height() + 7) / 8, 1);
}

void RasterMergePass::recordSeedCopy(PassContext& pc) {
    recordDepthCopy(pc.cmd, pc.buffer(seed_).buffer, pc.image(t_.depth).image, pc.graph.width(),
                    pc.graph.height());
}

void RasterMergePass::recordListed(PassContext& pc) {
    beginRendering(pc, {ColorTarget{t_.ids, {}, false, {}}}, DepthTarget{t_.depth, {}, false});
    bind(pc, listedLayout_, listedSet_, listed_);
    vkCmdDrawIndirect(pc.cmd, pc.buffer(raster_.args).buffer, 0, 1, 16);
    endRendering(pc);
}

void RasterMergePass::recordMerge(PassContext& pc) {
    // Compute mode: nothing drew before, so this pass clears (ids 0: no geometry; depth 0).
    const bool clear = !raster_.hybrid;
    ColorTarget ids{t_.ids, {}, clear, {}};
    ids.clearValue.uint32[0] = 0;
    beginRendering(pc, {ids},
                   DepthTarget{t_.depth, samples_ > 1 ? resolved_ : ResourceHandle{}, clear});
    bind(pc, mergeLayout_, mergeSet_, merge_);
    vkCmdDraw(pc.cmd, 3, 1, 0, 0);
    endRendering(pc);
}

} // namespace tp::vis
