#pragma once
// A pass's own descriptor set (set 1): layout, pool and one set, made from a list of
// bindings whose numbers come from the pipeline's shaders/<pipeline>/<pipeline>_shared.h.
// Passes make theirs with FrameGraph::createPassSet from their declared uses; these are the
// Vulkan calls under it.
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace tp {

class GpuContext;

struct SetBinding {
    uint32_t binding;
    VkDescriptorType type;
};

struct PassSet {
    std::string pass; // the pass whose uses it was made from (FrameGraph::createPassSet)
    std::vector<SetBinding> bindings; // what the pipelines' shaders are checked against
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
};

PassSet createPassSet(GpuContext& ctx, const std::vector<SetBinding>& bindings);
void destroyPassSet(GpuContext& ctx, PassSet& set);
void writeImageDescriptor(GpuContext& ctx, VkDescriptorSet set, uint32_t binding,
                          VkDescriptorType type, VkImageView view, VkImageLayout layout,
                          VkSampler sampler);
void writeBufferDescriptor(GpuContext& ctx, VkDescriptorSet set, uint32_t binding, VkBuffer buffer,
                           VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);

} // namespace tp
