#pragma once
// One scene draw as every pass records it: DrawPush (the material and a pass's own word
// pad0: multipass forward's light index), cull mode from the material's double-sidedness,
// the indexed draw. The caller binds the pipeline, the scene set and the index buffer.
#include <cstdint>

#include <vulkan/vulkan.h>

namespace tp {
struct DrawItem;
}

namespace tp::passes {

void recordSceneDraw(VkCommandBuffer cmd, VkPipelineLayout layout, const DrawItem& d, uint32_t pad0 = 0);

} // namespace tp::passes
