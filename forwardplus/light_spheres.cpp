#include "forwardplus/light_spheres.h"

#include <algorithm>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpuscene/scene_gpu.h"
#include "forwardplus/forwardplus_shared.h"

namespace tp::fp {

LightSpheres::~LightSpheres() {
    if (pipeline_) vkDestroyPipeline(ctx_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    destroyPassSet(ctx_, set_);
}

ResourceHandle LightSpheres::plan(FrameGraph& graph) {
    lightCount_ = uint32_t(scene_.lightsGpu().size());
    ResourceHandle spheres = graph.createBuffer(
        "light_spheres", std::max<VkDeviceSize>(VkDeviceSize(lightCount_) * 16, 16),
        "per light: view-space bounding sphere (centre, padded range) for the culling");
    graph.addPass("light_spheres", {{spheres, Use::StorageWrite, TP_FP_BINDING_SPHERES}},
                  [this](PassContext& pc) { record(pc); });
    return spheres;
}

void LightSpheres::prepare(FrameGraph& graph) {
    set_ = graph.createPassSet("light_spheres");
    layout_ = scene_.createPipelineLayout(set_.layout);
    pipeline_ = createComputePipeline(ctx_, "fp_light_spheres_comp",
                                      scene_.specConstants(AlphaMode::Opaque), layout_, &set_);
}

void LightSpheres::record(PassContext& pc) {
    if (lightCount_ == 0) return;
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_COMPUTE);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    gpu::DrawPush push{0, 0, 0, 0};
    push.TP_FP_SPHERE_COUNT = lightCount_;
    vkCmdPushConstants(pc.cmd, layout_, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
    // 64 lights per group, at most 65,535 groups per row (the smallest limit Vulkan allows).
    const uint32_t groups = (lightCount_ + 63) / 64;
    const uint32_t x = std::min(groups, 65535u);
    vkCmdDispatch(pc.cmd, x, (groups + x - 1) / x, 1);
}

} // namespace tp::fp
