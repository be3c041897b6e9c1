#include "core/gpu/descriptors.h"

#include "core/gpu/context.h"
#include "core/gpu/vk_check.h"

namespace tp {

PassSet createPassSet(GpuContext& ctx, const std::vector<SetBinding>& bindings) {
    PassSet s;
    std::vector<VkDescriptorSetLayoutBinding> lb;
    std::vector<VkDescriptorPoolSize> sizes;
    for (const SetBinding& b : bindings) {
        lb.push_back({b.binding, b.type, 1, VK_SHADER_STAGE_ALL, nullptr});
        sizes.push_back({b.type, 1});
    }
    VkDescriptorSetLayoutCreateInfo li{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    li.bindingCount = uint32_t(lb.size());
    li.pBindings = lb.data();
    VK_CHECK(vkCreateDescriptorSetLayout(ctx.device, &li, nullptr, &s.layout));
    VkDescriptorPoolCreateInfo pi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pi.maxSets = 1;
    pi.poolSizeCount = uint32_t(sizes.size());
    pi.pPoolSizes = sizes.data();
    VK_CHECK(vkCreateDescriptorPool(ctx.device, &pi, nullptr, &s.pool));
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = s.pool;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &s.layout;
    VK_CHECK(vkAllocateDescriptorSets(ctx.device, &ai, &s.set));
    return s;
}

void destroyPassSet(GpuContext& ctx, PassSet& s) {
    if (s.pool) vkDestroyDescriptorPool(ctx.device, s.pool, nullptr);
    if (s.layout) vkDestroyDescriptorSetLayout(ctx.device, s.layout, nullptr);
    s = {};
}

namespace {

void writeDescriptor(GpuContext& ctx, VkDescriptorSet set, uint32_t binding, VkDescriptorType type,
                     const VkDescriptorImageInfo* image, const VkDescriptorBufferInfo* buffer) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    w.pImageInfo = image;
    w.pBufferInfo = buffer;
    vkUpdateDescriptorSets(ctx.device, 1, &w, 0, nullptr);
}

} // namespace

void writeImageDescriptor(GpuContext& ctx, VkDescriptorSet set, uint32_t binding,
                          VkDescriptorType type, VkImageView view, VkImageLayout layout,
                          VkSampler sampler) {
    VkDescriptorImageInfo ii{sampler, view, layout};
    writeDescriptor(ctx, set, binding, type, &ii, nullptr);
}

void writeBufferDescriptor(GpuContext& ctx, VkDescriptorSet set, uint32_t binding,
                           VkBuffer buffer, VkDescriptorType type) {
    VkDescriptorBufferInfo bi{buffer, 0, VK_WHOLE_SIZE};
    writeDescriptor(ctx, set, binding, type, nullptr, &bi);
}

} // namespace tp
