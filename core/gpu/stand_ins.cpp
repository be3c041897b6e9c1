#include "core/gpu/stand_ins.h"

#include "core/gpu/context.h"
#include "core/gpu/vk_check.h"

namespace tp {

Buffer createStandInBuffer(GpuContext& ctx, const LedgerTag& tag,
                           const std::array<uint32_t, 4>& words) {
    return createBufferWithData(ctx, words.data(), sizeof(words),
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, tag);
}

VkSampler createNearestClampSampler(GpuContext& ctx) {
    VkSamplerCreateInfo si{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    si.magFilter = si.minFilter = VK_FILTER_NEAREST;
    si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    VkSampler sampler;
    VK_CHECK(vkCreateSampler(ctx.device, &si, nullptr, &sampler));
    return sampler;
}

} // namespace tp
