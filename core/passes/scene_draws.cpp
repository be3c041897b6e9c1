#include "core/passes/scene_draws.h"

#include "core/render/scene_gpu.h"

namespace tp::passes {

void recordSceneDraw(VkCommandBuffer cmd, VkPipelineLayout layout, const DrawItem& d, uint32_t pad0) {
    gpu::DrawPush push{d.material, 0, 0, 0};
    push.pad0 = pad0;
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
    vkCmdSetCullMode(cmd, d.doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT);
    vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, d.vertexOffset, 0);
}

} // namespace tp::passes
