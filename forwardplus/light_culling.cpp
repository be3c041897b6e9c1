#include "forwardplus/light_culling.h"

#include <algorithm>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/resources.h"
#include "core/gpu/stand_ins.h"
#include "core/gpu/vk_check.h"
#include "core/gpuscene/scene_gpu.h"
#include "forwardplus/forwardplus_shared.h"

namespace tp::fp {

std::string subgroupCullingUnsupported(const DeviceCaps& caps) {
    if (!(caps.subgroupStages & VK_SHADER_STAGE_COMPUTE_BIT))
        return "the device has no subgroup operations in compute shaders";
    const uint32_t need = VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_VOTE_BIT |
                          VK_SUBGROUP_FEATURE_ARITHMETIC_BIT | VK_SUBGROUP_FEATURE_BALLOT_BIT;
    if ((caps.subgroupOps & need) != need)
        return "the device lacks subgroup vote, arithmetic or ballot operations in compute shaders";
    if (!caps.computeFullSubgroups)
        return "the device cannot guarantee full subgroups of its subgroup size to a compute "
               "workgroup";
    if (caps.subgroupSize > 64)
        return "the device's subgroups have " + std::to_string(caps.subgroupSize) +
               " lanes (at most 64 supported)";
    return {};
}

LightCulling::~LightCulling() {
    if (pipeline_) vkDestroyPipeline(ctx_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    destroyPassSet(ctx_, set_);
    if (sampler_) vkDestroySampler(ctx_.device, sampler_, nullptr);
}

void LightCulling::plan(FrameGraph& graph, const CullResources& r) {
    // Uses with a binding are also the pass's descriptor set (prepare).
    std::vector<PassUse> uses = {{r.depth, Use::Sampled, TP_FP_BINDING_DEPTH},
                                 {r.tiles, Use::StorageWrite, TP_FP_BINDING_TILES},
                                 {r.indices, Use::StorageWrite, TP_FP_BINDING_INDICES}};
    if (config_.spheres) uses.push_back({r.spheres, Use::StorageRead, TP_FP_BINDING_SPHERES});
    if (config_.layout == TP_FP_LAYOUT_LINKED)
        uses.push_back({r.counter, Use::StorageWrite, TP_FP_BINDING_COUNTER});
    if (config_.clustered)
        uses.push_back({r.masks, Use::StorageWrite, TP_FP_BINDING_CLUSTER_MASKS});
    blendBounds_ = r.blendBounds.valid();
    if (blendBounds_) uses.push_back({r.blendBounds, Use::StorageRead, TP_FP_BINDING_BLEND_BOUNDS});
    centreBounds_ = r.centreBounds.valid();
    if (centreBounds_)
        uses.push_back({r.centreBounds, Use::StorageRead, TP_FP_BINDING_CENTRE_BOUNDS});
    graph.addPass("light_culling", uses, [this](PassContext& pc) { record(pc); });
}

void LightCulling::prepare(FrameGraph& graph, VkBuffer params) {
    sampler_ = createNearestClampSampler(ctx_);
    std::vector<ExternalBuffer> externals = {{TP_FP_BINDING_PARAMS, params}};
    if (!blendBounds_) {
        noBlendBounds_ =
            createStandInBuffer(ctx_,
                                {graph.owner(), "", "blended_bounds_unused",
                                 "stand-in: no blended draws, no blended depth bounds"},
                                {TP_LA_BLEND_EMPTY, TP_LA_BLEND_EMPTY, 0, 0});
        externals.push_back({TP_FP_BINDING_BLEND_BOUNDS, noBlendBounds_.buffer});
    }
    if (!centreBounds_) {
        noCentreBounds_ = createStandInBuffer(
            ctx_,
            {graph.owner(), "", "centre_bounds_unused",
             "stand-in: every opaque fragment is shaded at its own sample (1x, --msaa-shading sample)"},
            {TP_LA_BLEND_EMPTY, TP_LA_BLEND_EMPTY, 0, 0});
        externals.push_back({TP_FP_BINDING_CENTRE_BOUNDS, noCentreBounds_.buffer});
    }
    if (!config_.spheres) {
        // The shader declares the spheres whatever kSpheres says.
        noSpheres_ = createStandInBuffer(
            ctx_, {graph.owner(), "", "light_spheres_unused",
                   "stand-in: each candidate's sphere is computed in the culling"});
        externals.push_back({TP_FP_BINDING_SPHERES, noSpheres_.buffer});
    }
    set_ = graph.createPassSet("light_culling", sampler_, externals);
    layout_ = scene_.createPipelineLayout(set_.layout);

    const bool msaa = config_.samples > 1;
    const bool subgroup = config_.subgroupLanes > 0;
    static const char* const kLayouts[] = {"compact", "fixed",
                                           "linked"}; // TP_FP_LAYOUT_*: the variants
    std::string name = std::string("fp_cull_") + kLayouts[config_.layout] +
                       (config_.clustered ? "_clustered" : "") + (msaa ? "_ms" : "") +
                       (subgroup ? "_subgroup" : "") + "_comp";
    std::vector<SpecConstant> spec = scene_.specConstants(AlphaMode::Opaque);
    spec.push_back({TP_SPEC_TILE_SIZE, config_.grid.tileSize});
    spec.push_back({TP_SPEC_SAMPLES, config_.samples});
    spec.push_back({TP_FP_SPEC_TWO_LISTS, config_.twoLists ? 1u : 0u});
    spec.push_back({TP_FP_SPEC_BINNED, config_.binned ? 1u : 0u});
    spec.push_back({TP_FP_SPEC_SLICES, config_.slices});
    spec.push_back({TP_FP_SPEC_BLENDED_SPAN, config_.blendedSpan ? 1u : 0u});
    spec.push_back({TP_FP_SPEC_SPHERES, config_.spheres ? 1u : 0u});
    spec.push_back({TP_FP_SPEC_CENTRE_BOUNDS, centreBounds_ ? 1u : 0u});
    if (subgroup) spec.push_back({TP_FP_SPEC_CULL_LANES, config_.subgroupLanes});
    pipeline_ = createComputePipeline(ctx_, name, spec, layout_, &set_, config_.subgroupLanes);
}

// Candidates per culling dispatch: one invocation culls a whole tile, and lavapipe ends
// an invocation after 65,535 loop iterations (forwardplus_shared.h); a candidate costs
// one iteration (two for linked: count, then fill), plus, clustered, up to one per slice
// and a slice row write per 32 stored.
uint32_t LightCulling::batchSize() const {
    const uint32_t perCandidate = (config_.layout == TP_FP_LAYOUT_LINKED ? 2 : 1) +
                                  (config_.clustered ? config_.slices + 1 : 0);
    return std::max(1u, TP_FP_CULL_LOOP_BUDGET / perCandidate);
}

void LightCulling::record(PassContext& pc) {
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_COMPUTE);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    const uint32_t batch = batchSize();
    const uint32_t batches = std::max(1u, (config_.mostTested + batch - 1) / batch);
    const bool linked = config_.layout == TP_FP_LAYOUT_LINKED;
    for (uint32_t i = 0; i < batches; ++i) {
        if (i > 0) {
            // Hand-written (the graph orders passes, not dispatches within one): the next
            // batch continues the lists, counts and slice words this one wrote.
            memoryBarrier(
                pc.cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        }
        // linked prepends each batch, so it takes them last to first.
        const uint32_t b = linked ? batches - 1 - i : i;
        gpu::DrawPush push{0, 0, 0, 0};
        push.TP_FP_CULL_FIRST = b * batch;
        push.TP_FP_CULL_END = b + 1 == batches ? 0xffffffffu : (b + 1) * batch;
        push.TP_FP_CULL_INITIAL = i == 0 ? 1u : 0u;
        vkCmdPushConstants(pc.cmd, layout_, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
        if (config_.subgroupLanes >
            0) // one workgroup (one subgroup) per tile: light_culling_subgroup.comp
            vkCmdDispatch(pc.cmd, config_.grid.tilesX, config_.grid.tilesY, 1);
        else // one invocation per tile, 8 x 8 tiles per workgroup (light_culling.comp)
            vkCmdDispatch(pc.cmd, (config_.grid.tilesX + 7) / 8, (config_.grid.tilesY + 7) / 8, 1);
    }
    dispatches_ = batches;
}

} // namespace tp::fp
