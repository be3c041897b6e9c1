#include "core/gpu/readback.h"

#include <cstring>
#include <stdexcept>

#include <glm/gtc/packing.hpp>

#include "core/gpu/context.h"

namespace tp {
namespace {

// The copy's writes become visible to the host's read after the fence wait.
void transferToHostBarrier(VkCommandBuffer cmd) {
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

// Copies the whole of `image` (mip 0) into a host-visible buffer and returns the bytes.
std::vector<uint8_t> copyToHost(GpuContext& ctx, const Image& image, uint32_t texelBytes) {
    VkDeviceSize size = VkDeviceSize(image.desc.width) * image.desc.height * texelBytes;
    Buffer staging = createBuffer(ctx, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::Readback,
                                  {"readback", "", "staging", "readback"});
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferImageCopy region{};
        region.imageSubresource = {image.aspect, 0, 0, 1};
        region.imageExtent = {image.desc.width, image.desc.height, 1};
        vkCmdCopyImageToBuffer(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               staging.buffer, 1, &region);
        transferToHostBarrier(cmd);
    });
    std::vector<uint8_t> bytes(size);
    std::memcpy(bytes.data(), staging.mapped, size);
    return bytes;
}

} // namespace

ImageRGBA readbackColor(GpuContext& ctx, const Image& image) {
    if (image.desc.samples != VK_SAMPLE_COUNT_1_BIT)
        throw std::logic_error("readbackColor: multisampled images must be resolved first");
    VkFormat f = image.desc.format;
    uint32_t texel = formatBytesPerTexel(f);
    std::vector<uint8_t> bytes = copyToHost(ctx, image, texel);
    ImageRGBA out(image.desc.width, image.desc.height);
    size_t n = out.pixelCount();
    for (size_t i = 0; i < n; ++i) {
        float* dst = &out.rgba[i * 4];
        const uint8_t* src = &bytes[i * texel];
        if (f == VK_FORMAT_R32G32B32A32_SFLOAT) {
            std::memcpy(dst, src, 16);
        } else if (f == VK_FORMAT_R16G16B16A16_SFLOAT) {
            uint16_t h[4];
            std::memcpy(h, src, 8);
            for (int c = 0; c < 4; ++c)
                dst[c] = glm::unpackHalf1x16(h[c]);
        } else if (f == VK_FORMAT_R8G8B8A8_UNORM || f == VK_FORMAT_R8G8B8A8_SRGB) {
            for (int c = 0; c < 4; ++c)
                dst[c] = src[c] / 255.0f;
        } else if (f == VK_FORMAT_R32_SFLOAT || f == VK_FORMAT_R32_UINT) {
            float v;
            if (f == VK_FORMAT_R32_SFLOAT) {
                std::memcpy(&v, src, 4);
            } else {
                uint32_t u;
                std::memcpy(&u, src, 4);
                v = float(u);
            }
            dst[0] = dst[1] = dst[2] = v;
            dst[3] = 1.0f;
        } else {
            throw std::logic_error(std::string("readbackColor: unsupported format ") +
                                   formatName(f));
        }
    }
    return out;
}

ImageR32 readbackDepth(GpuContext& ctx, const Image& image) {
    if (image.desc.format != VK_FORMAT_D32_SFLOAT || image.desc.samples != VK_SAMPLE_COUNT_1_BIT)
        throw std::logic_error("readbackDepth: needs a single-sample D32_SFLOAT image");
    std::vector<uint8_t> bytes = copyToHost(ctx, image, 4);
    ImageR32 out{image.desc.width, image.desc.height, std::vector<float>(bytes.size() / 4)};
    std::memcpy(out.r.data(), bytes.data(), bytes.size());
    return out;
}

std::vector<uint8_t> readbackBuffer(GpuContext& ctx, const Buffer& buffer) {
    Buffer staging = createBuffer(ctx, buffer.size, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                  MemoryKind::Readback, {"readback", "", "staging", "readback"});
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferCopy copy{0, 0, buffer.size};
        vkCmdCopyBuffer(cmd, buffer.buffer, staging.buffer, 1, &copy);
        transferToHostBarrier(cmd);
    });
    std::vector<uint8_t> bytes(buffer.size);
    std::memcpy(bytes.data(), staging.mapped, buffer.size);
    return bytes;
}

} // namespace tp
