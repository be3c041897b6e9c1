#pragma once
// The compute rasterizer's samples into the visibility targets (--vis-raster compute|hybrid;
// raster_pass.h, docs/visbuffer.md "The compute rasterizer"):
//   vis_raster_hw     (hybrid) the triangles vis_raster listed for the hardware, one indirect
//                     draw over the targets the visibility pass left (masked draws in them).
//   vis_raster_merge  one triangle over the framebuffer: per sample the 64-bit word becomes the
//                     id and the depth through the GREATER depth test, so the nearer of the
//                     hardware's and the compute rasterizer's surfaces stays; it clears the
//                     targets first in compute mode (no pass drew before it) and resolves the
//                     MSAA depth (sample 0) into "depth".
// Separate passes, each with its own set: a pass's set must be what every pipeline in it
// declares (core/gpu/shader_reflection.h).
#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "visbuffer/raster_pass.h"
#include "visbuffer/visibility_pass.h"

namespace tp {
class GpuContext;
class SceneGpu;

namespace vis {

class RasterMergePass {
  public:
    RasterMergePass(GpuContext& ctx, SceneGpu& scene) : ctx_(ctx), scene_(scene) {}
    ~RasterMergePass();
    RasterMergePass(const RasterMergePass&) = delete;
    RasterMergePass& operator=(const RasterMergePass&) = delete;

    // targets: the visibility pass's (made by it, drawn by it in hybrid mode); resolvedDepth:
    // the single-sample "depth" (targets.depth itself at 1x).
    void plan(FrameGraph& graph, uint32_t samples, const VisibilityTargets& targets,
              ResourceHandle resolvedDepth, const RasterTargets& raster);
    void prepare(FrameGraph& graph);

  private:
    void recordListed(PassContext& pc);
    void recordMerge(PassContext& pc);
    void bind(PassContext& pc, VkPipelineLayout layout, const PassSet& set, VkPipeline pipeline);
    GpuContext& ctx_;
    SceneGpu& scene_;
    uint32_t samples_ = 1;
    VisibilityTargets t_;
    ResourceHandle resolved_;
    RasterTargets raster_;
    PassSet listedSet_, mergeSet_;
    VkPipelineLayout listedLayout_ = VK_NULL_HANDLE, mergeLayout_ = VK_NULL_HANDLE;
    VkPipeline listed_ = VK_NULL_HANDLE, merge_ = VK_NULL_HANDLE;
};

} // namespace vis
} // namespace tp
