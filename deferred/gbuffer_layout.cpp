#include "deferred/gbuffer_layout.h"

#include "core/gpu/context.h"
#include "core/gpu/ledger.h"

namespace tp {
namespace {

// Colour attachment + sampled at this sample count, optimal tiling.
bool canRenderAndSample(GpuContext& ctx, VkFormat format, uint32_t samples) {
    VkImageFormatProperties props{};
    VkResult r = vkGetPhysicalDeviceImageFormatProperties(
        ctx.physical, format, VK_IMAGE_TYPE_2D, VK_IMAGE_TILING_OPTIMAL,
        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, 0, &props);
    return r == VK_SUCCESS && (props.sampleCounts & samples) != 0;
}

} // namespace

uint32_t GBufferLayout::bytesPerSample() const {
    uint32_t bytes = formatBytesPerTexel(depth);
    for (const GBufferTarget& t : colors)
        bytes += formatBytesPerTexel(t.format);
    return bytes;
}

GBufferLayout planGBufferLayout(GpuContext& ctx, const SceneFeatures& features,
                                def::GBuffer gbuffer, uint32_t samples) {
    GBufferLayout g;
    g.wide = gbuffer == def::GBuffer::Wide;
    g.emissive = features.emissive;
    g.samples = samples;
    if (g.wide) {
        g.colors = {
            {"gbuffer_base", VK_FORMAT_R32G32B32A32_SFLOAT, "base colour rgb, occlusion a (fp32)"},
            {"gbuffer_normal", VK_FORMAT_R32G32B32A32_SFLOAT, "normal xyz (fp32)"},
            {"gbuffer_rough_metal", VK_FORMAT_R32G32_SFLOAT, "roughness, metallic (fp32)"}};
    } else {
        g.colors = {
            {"gbuffer_base", VK_FORMAT_R8G8B8A8_SRGB, "base colour rgb (sRGB), occlusion a"},
            {"gbuffer_normal", VK_FORMAT_R16G16_SNORM, "octahedral normal"},
            {"gbuffer_rough_metal", VK_FORMAT_R8G8_UNORM, "roughness, metallic"}};
    }
    if (g.emissive) {
        VkFormat f = VK_FORMAT_R32G32B32A32_SFLOAT;
        if (!g.wide)
            f = canRenderAndSample(ctx, VK_FORMAT_B10G11R11_UFLOAT_PACK32, g.samples)
                    ? VK_FORMAT_B10G11R11_UFLOAT_PACK32
                    : VK_FORMAT_R16G16B16A16_SFLOAT;
        g.colors.push_back({"gbuffer_emissive", f, "emissive radiance rgb"});
    }
    return g;
}

} // namespace tp
