#pragma once
// Image layout transitions written by hand, for the few places outside the frame graph
// (texture uploads, the viewer's swapchain image); each call site says why it needs one.
// Buffers and memory: memoryBarrier (resources.h).
#include <vulkan/vulkan.h>

namespace tp {

// A transition of `range` (by default the colour aspect of mip 0, layer 0) from layout `from`
// to `to`, after srcStage/srcAccess and before dstStage/dstAccess.
void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                  VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                  VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess,
                  const VkImageSubresourceRange& range = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1});

} // namespace tp
