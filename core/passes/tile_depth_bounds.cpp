#include "core/passes/tile_depth_bounds.h"

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/stand_ins.h"
#include "core/gpuscene/scene_gpu.h"
#include "passes/tiled_lighting.h"

namespace tp {

TileDepthBounds::~TileDepthBounds() {
    if (pipeline_) vkDestroyPipeline(ctx_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    if (sampler_) vkDestroySampler(ctx_.device, sampler_, nullptr);
    destroyPassSet(ctx_, set_);
}

ResourceHandle TileDepthBounds::plan(FrameGraph& graph, ResourceHandle depth, uint32_t samples,
                                     const la::TileGrid& grid) {
    grid_ = grid;
    samples_ = samples;
    ResourceHandle bounds =
        graph.createBuffer("tile_depth_bounds", uint64_t(grid.count()) * 16,
                           "per tile: nearest and farthest geometry depth, sees the sky");
    graph.addPass("tile_depth_bounds",
                  {{depth, Use::Sampled, TP_TL_BINDING_DEPTH},
                   {bounds, Use::StorageWrite, TP_TL_BINDING_TILE_DEPTH}},
                  [this](PassContext& pc) { record(pc); });
    return bounds;
}

void TileDepthBounds::prepare(FrameGraph& graph) {
    sampler_ = createNearestClampSampler(ctx_); // texelFetch only
    set_ = graph.createPassSet("tile_depth_bounds", sampler_);
    layout_ = scene_.createPipelineLayout(set_.layout);
    std::vector<SpecConstant> spec = scene_.specConstants(AlphaMode::Opaque);
    spec.push_back({TP_SPEC_TILE_SIZE, grid_.tileSize});
    spec.push_back({TP_SPEC_SAMPLES, samples_});
    pipeline_ = createComputePipeline(
        ctx_, samples_ > 1 ? "tile_depth_bounds_ms_comp" : "tile_depth_bounds_comp", spec, layout_,
        &set_);
}

void TileDepthBounds::record(PassContext& pc) {
    scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_COMPUTE);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vkCmdDispatch(pc.cmd, grid_.tilesX, grid_.tilesY, 1);
}

} // namespace tp
