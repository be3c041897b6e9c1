#pragma once
// The depth pyramid (pass "depth_pyramid", compute; shaders/passes/depth_pyramid.comp): the
// depth a geometry pass wrote, reduced level by level to 1x1, each texel the farthest depth
// (reverse-Z: the smallest value) of every pixel and sample it covers. The late meshlet cull
// (--cull-geometry full, core/passes/meshlet_cull.h) tests each meshlet's nearest depth against
// the texels under its screen rectangle. Level 0 is half the frame, and a texel of level L
// covers exactly 2^(L+1) pixels a side (clipped at the frame's edge), so the reduction is
// conservative at any size (shaders/passes/depth_pyramid.h). docs/geometry.md, "Occlusion".
#include <vulkan/vulkan.h>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"

namespace tp {
class GpuContext;
class SceneGpu;
} // namespace tp

namespace tp::passes {

class DepthPyramid {
  public:
    DepthPyramid(GpuContext& ctx, const SceneGpu& scene);
    ~DepthPyramid();
    DepthPyramid(const DepthPyramid&) = delete;
    DepthPyramid& operator=(const DepthPyramid&) = delete;

    // Declares the pass: reads `depth` (the frame's size; sampled per sample under MSAA),
    // writes the buffer "depth_pyramid" (every level), which it returns.
    ResourceHandle plan(FrameGraph& graph, ResourceHandle depth);
    void prepare(FrameGraph& graph);
    uint32_t levels() const { return levels_; }

  private:
    void record(PassContext& pc);
    GpuContext& ctx_;
    const SceneGpu& scene_;
    ResourceHandle depth_, pyramid_;
    uint32_t width_ = 0, height_ = 0, samples_ = 1, levels_ = 0;
    PassSet set_;
    VkSampler sampler_ = VK_NULL_HANDLE;
    VkImageView depthView_ = VK_NULL_HANDLE; // a depth-stencil image's depth aspect
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

} // namespace tp::passes
