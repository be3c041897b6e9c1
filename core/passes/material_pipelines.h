#pragma once
// A graphics pass's pipelines by material: one per distinct set of texture indices among an
// alpha mode's draws, those indices compiled in as specialization constants
// (shaders/include/material.glsl, TP_MATERIAL_SPEC_TEXTURES; the fragment shader defines it).
// On lavapipe an absent texture is otherwise still sampled and a present one goes through a
// dynamic index (docs/forwardplus.md, "The material floor"); on the H200 the buffer's index
// loads and slot tests were most of what deferred's blended pass spent beyond Forward+'s
// (docs/deferred.md). Either way the same texel is sampled: the same image.
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/pipelines.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/scene/scene.h"

namespace tp {

class GpuContext;

class MaterialPipelines {
  public:
    explicit MaterialPipelines(GpuContext& ctx) : ctx_(ctx) {}
    ~MaterialPipelines();
    MaterialPipelines(const MaterialPipelines&) = delete;
    MaterialPipelines& operator=(const MaterialPipelines&) = delete;
    // The pipelines of `mode`'s draws, each `base` with its material's texture indices.
    void create(const SceneGpu& scene, AlphaMode mode, const GraphicsPipelineDesc& base);
    // The pipeline that draws `material` in `mode` (an index out of range: the one that reads
    // the indices from the material buffer). create(mode) first.
    VkPipeline pipeline(AlphaMode mode, uint32_t material) const;
    // Every draw of `mode` in SceneGpu::drawList's order, each with its material's pipeline
    // (bound when it changes), by `draw` (the index buffer is the caller's).
    template <typename Draw>
    void forEachDraw(const SceneGpu& scene, VkCommandBuffer cmd, AlphaMode mode, Draw draw) const;

  private:
    GpuContext& ctx_;
    std::vector<VkPipeline> byMaterial_[3]; // by AlphaMode, then by material; last: out of range
    std::vector<VkPipeline> pipelines_;     // owned: materials with the same indices share one
};


template <typename Draw>
void MaterialPipelines::forEachDraw(const SceneGpu& scene, VkCommandBuffer cmd, AlphaMode mode,
                                    Draw draw) const {
    VkPipeline bound = VK_NULL_HANDLE;
    for (const DrawItem* item : scene.drawList(DrawFilter(mode))) {
        VkPipeline p = pipeline(mode, item->material);
        if (p != bound) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p);
        bound = p;
        draw(*item);
    }
}

} // namespace tp
