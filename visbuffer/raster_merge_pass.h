#pragma once
// The compute rasterizer's samples into the visibility targets (--vis-raster compute|hybrid;
// raster_pass.h, docs/visbuffer.md "The compute rasterizer"):
//   vis_raster_seed       (1x) per pixel the 64-bit word as the id, stored into the id image,
//   vis_raster_seed_copy  and the depth, an fp32 plane copied into the depth image: their
//                         first contents, before any hardware draw (the visibility pass keeps
//                         them). No graphics pass: on the H200 those run on 4 of 132 SMs.
//   vis_raster_hw         (hybrid) the triangles vis_raster listed for the hardware, one
//                         indirect draw over the targets the visibility pass left (masked draws
//                         in them; at 1x over the seed too, through the GREATER depth test).
//   vis_raster_merge      (MSAA, where a multisampled depth image cannot be a copy's
//                         destination) one triangle over the framebuffer: per sample the 64-bit
//                         word becomes the id and the depth through the GREATER depth test, so
//                         the nearer of the hardware's and the compute rasterizer's surfaces
//                         stays; it clears the targets first in compute mode (no pass drew
//                         before it) and resolves the MSAA depth (sample 0) into "depth".
// At equal depth the seed keeps the compute rasterizer's surface (the hardware's fails GREATER
// after it), the merge the hardware's: coplanar overlaps of a hardware and a compute triangle.
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

    // At 1x the seed's passes, before the visibility pass (true); under MSAA nothing (false).
    bool planSeed(FrameGraph& graph, uint32_t samples, const VisibilityTargets& targets,
                  const RasterTargets& raster);
    // After the visibility pass: hybrid's listed triangles, and under MSAA the merge.
    // targets: the visibility pass's (drawn by it in hybrid mode); resolvedDepth: the
    // single-sample "depth" (targets.depth itself at 1x).
    void plan(FrameGraph& graph, uint32_t samples, const VisibilityTargets& targets,
              ResourceHandle resolvedDepth, const RasterTargets& raster);
    void prepare(FrameGraph& graph);

  private:
    void recordSeed(PassContext& pc);
    void recordSeedCopy(PassContext& pc);
    void recordListed(PassContext& pc);
    void recordMerge(PassContext& pc);
    void bind(PassContext& pc, VkPipelineLayout layout, const PassSet& set, VkPipeline pipeline);
    GpuContext& ctx_;
    SceneGpu& scene_;
    uint32_t samples_ = 1;
    VisibilityTargets t_;
    ResourceHandle resolved_;
    RasterTargets raster_;
    ResourceHandle seed_; // 1x: the depths, for the copy (vis_raster_seed.comp)
    PassSet seedSet_, listedSet_, mergeSet_;
    VkPipelineLayout seedLayout_ = VK_NULL_HANDLE, listedLayout_ = VK_NULL_HANDLE,
                     mergeLayout_ = VK_NULL_HANDLE;
    VkPipeline seedPipeline_ = VK_NULL_HANDLE, listed_ = VK_NULL_HANDLE, merge_ = VK_NULL_HANDLE;
};

} // namespace vis
} // namespace tp
