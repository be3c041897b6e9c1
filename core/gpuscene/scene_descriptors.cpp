// SceneGpu: textures (upload + mip chain) and descriptor set 0.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/gpu/context.h"
#include "core/gpu/descriptors.h"
#include "core/gpu/vk_check.h"
#include "core/gpuscene/scene_gpu.h"

namespace tp {
namespace {

uint32_t mipCount(uint32_t w, uint32_t h) {
    return 1 + uint32_t(std::floor(std::log2(double(std::max(w, h)))));
}

} // namespace

void SceneGpu::uploadTextures() {
    std::vector<Texture> textures = scene_.textures;
    if (textures.empty()) // the array binding needs one element; never sampled (index -1)
        textures.push_back({"placeholder", 1, 1, false, {255, 255, 255, 255}});
    VkDeviceSize total = 0;
    for (const Texture& t : textures)
        total += t.rgba8.size();
    Buffer staging = createBuffer(ctx_, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::Upload,
                                  {"staging", "", "staging", "upload"});
    for (const Texture& t : textures) {
        ImageDesc d;
        d.format = t.srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
        d.width = t.width;
        d.height = t.height;
        d.mipLevels = mipCount(t.width, t.height);
        d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                  VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        textures_.push_back(
            createImage(ctx_, d, {"scene", "", "texture:" + t.name, "material texture"}));
    }
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
        VkDeviceSize offset = 0;
        for (size_t i = 0; i < textures.size(); ++i) {
            std::memcpy(static_cast<uint8_t*>(staging.mapped) + offset, textures[i].rgba8.data(),
                        textures[i].rgba8.size());
            recordImageUpload(cmd, textures_[i], staging.buffer, offset);
            offset += textures[i].rgba8.size();
        }
    });
    VkSamplerCreateInfo s{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    s.magFilter = s.minFilter = VK_FILTER_LINEAR;
    s.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    s.addressModeU = s.addressModeV = s.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    s.maxLod = VK_LOD_CLAMP_NONE;
    VK_CHECK(vkCreateSampler(ctx_.device, &s, nullptr, &sampler_));
}

void SceneGpu::createDescriptors() {
    VkDescriptorSetLayoutCreateInfo empty{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    VK_CHECK(vkCreateDescriptorSetLayout(ctx_.device, &empty, nullptr, &emptySetLayout_));
    const uint32_t texCount = uint32_t(textures_.size());
    VkDescriptorSetLayoutBinding b[5] = {
        {TP_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_ALL, nullptr},
        {TP_BINDING_VERTICES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_ALL, nullptr},
        {TP_BINDING_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_ALL, nullptr},
        {TP_BINDING_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_ALL, nullptr},
        {TP_BINDING_TEXTURES, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, texCount,
         VK_SHADER_STAGE_ALL, nullptr},
    };
    VkDescriptorSetLayoutCreateInfo li{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    li.bindingCount = 5;
    li.pBindings = b;
    VK_CHECK(vkCreateDescriptorSetLayout(ctx_.device, &li, nullptr, &setLayout_));
    VkDescriptorPoolSize sizes[3] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                     {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3},
                                     {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, texCount}};
    VkDescriptorPoolCreateInfo pi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pi.maxSets = 1;
    pi.poolSizeCount = 3;
    pi.pPoolSizes = sizes;
    VK_CHECK(vkCreateDescriptorPool(ctx_.device, &pi, nullptr, &pool_));
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = pool_;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &setLayout_;
    VK_CHECK(vkAllocateDescriptorSets(ctx_.device, &ai, &set_));

    VkDescriptorBufferInfo frame{frameBuffer_.buffer, 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo verts{vertices_.buffer, 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo mats{materials_.buffer, 0, VK_WHOLE_SIZE};
    std::vector<VkDescriptorImageInfo> images;
    for (const Image& t : textures_)
        images.push_back({sampler_, t.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
    VkWriteDescriptorSet w[4] = {};
    for (int i = 0; i < 4; ++i) {
        w[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        w[i].dstSet = set_;
        w[i].descriptorCount = 1;
        w[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    }
    w[0].dstBinding = TP_BINDING_FRAME;
    w[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    w[0].pBufferInfo = &frame;
    w[1].dstBinding = TP_BINDING_VERTICES;
    w[1].pBufferInfo = &verts;
    w[2].dstBinding = TP_BINDING_MATERIALS;
    w[2].pBufferInfo = &mats;
    w[3].dstBinding = TP_BINDING_TEXTURES;
    w[3].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w[3].descriptorCount = texCount;
    w[3].pImageInfo = images.data();
    vkUpdateDescriptorSets(ctx_.device, 4, w, 0, nullptr);
}

void SceneGpu::writeLightDescriptor() {
    writeBufferDescriptor(ctx_, set_, TP_BINDING_LIGHTS, lights_.buffer);
}

} // namespace tp
