#include "core/gpu/readback.h"

#include <cstring>
#include <stdexcept>

#include <glm/gtc/packing.hpp>
#ifdef __x86_64__
#include <immintrin.h>
#endif

#include "core/gpu/context.h"

namespace tp {
namespace {

// The copy's writes become visible to the host's read after the fence wait.
void transferToHostBarrier(VkCommandBuffer cmd) {
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

// Copies the whole of `image` (mip 0) into a host-visible buffer (mapped; valid until the
// returned Buffer is destroyed), so the caller converts straight from it.
Buffer copyToHost(GpuContext& ctx, const Image& image, uint32_t texelBytes) {
    VkDeviceSize size = VkDeviceSize(image.desc.width) * image.desc.height * texelBytes;
    Buffer staging = createBuffer(ctx, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::Readback,
                                  {"readback", "", "staging", "readback"});
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferImageCopy region{};
        // One aspect a copy: a depth-stencil image gives its depth.
        const VkImageAspectFlags aspect = image.aspect & VK_IMAGE_ASPECT_DEPTH_BIT
                                              ? VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT)
                                              : image.aspect;
        region.imageSubresource = {aspect, 0, 0, 1};
        region.imageExtent = {image.desc.width, image.desc.height, 1};
        vkCmdCopyImageToBuffer(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               staging.buffer, 1, &region);
        transferToHostBarrier(cmd);
    });
    return staging;
}

// Half to float is exact (every half is a float); glm converts one value at a time in software,
// which at 1080p (8.3 M values) cost the viewer tens of milliseconds a view. Where the CPU has
// F16C, eight at a time in hardware: the same values (NaNs stay NaNs).
bool readableColor(VkFormat f) {
    for (VkFormat ok : {VK_FORMAT_R32G32B32A32_SFLOAT, VK_FORMAT_R16G16B16A16_SFLOAT,
                        VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_R32_SFLOAT,
                        VK_FORMAT_R32_UINT})
        if (f == ok) return true;
    return false;
}

// One texel of the 8-bit and one-channel formats (debug images) into RGBA float.
void texelToRgba(VkFormat f, const uint8_t* src, float* dst) {
    if (f == VK_FORMAT_R8G8B8A8_UNORM || f == VK_FORMAT_R8G8B8A8_SRGB) {
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
    }
}

} // namespace

#ifdef __x86_64__ // GCC and clang: target attributes and __builtin_cpu_supports
__attribute__((target("f16c,avx"))) static void halfToFloatF16c(const uint16_t* src, float* dst,
                                                        size_t n) {
    size_t i = 0;
    for (; i + 8 <= n; i += 8)
        _mm256_storeu_ps(dst + i,
                         _mm256_cvtph_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(src + i))));
    for (; i < n; ++i)
        dst[i] = glm::unpackHalf1x16(src[i]);
}
#endif

void halfToFloat(const uint16_t* src, float* dst, size_t n) {
#ifdef __x86_64__ // GCC and clang: target attributes and __builtin_cpu_supports
    if (__builtin_cpu_supports("f16c") && __builtin_cpu_supports("avx"))
        return halfToFloatF16c(src, dst, n);
#endif
    for (size_t i = 0; i < n; ++i)
        dst[i] = glm::unpackHalf1x16(src[i]);
}

ImageRGBA readbackColor(GpuContext& ctx, const Image& image) {
    if (image.desc.samples != VK_SAMPLE_COUNT_1_BIT)
        throw std::logic_error("readbackColor: multisampled images must be resolved first");
    const VkFormat f = image.desc.format;
    const uint32_t texel = formatBytesPerTexel(f);
    ImageRGBA out(image.desc.width, image.desc.height);
    const size_t n = out.pixelCount();
    if (!readableColor(f)) // before anything is copied
        throw std::logic_error(std::string("readbackColor: unsupported format ") + formatName(f));
    const Buffer staging = copyToHost(ctx, image, texel);
    const auto* bytes = static_cast<const uint8_t*>(staging.mapped);
    if (f == VK_FORMAT_R32G32B32A32_SFLOAT)
        std::memcpy(out.rgba.data(), bytes, n * 16);
    else if (f == VK_FORMAT_R16G16B16A16_SFLOAT)
        halfToFloat(reinterpret_cast<const uint16_t*>(bytes), out.rgba.data(), n * 4);
    else
        for (size_t i = 0; i < n; ++i)
            texelToRgba(f, bytes + i * texel, &out.rgba[i * 4]);
    return out;
}

ImageR32 readbackDepth(GpuContext& ctx, const Image& image) {
    const VkFormat f = image.desc.format;
    if ((f != VK_FORMAT_D32_SFLOAT && f != VK_FORMAT_D32_SFLOAT_S8_UINT) ||
        image.desc.samples != VK_SAMPLE_COUNT_1_BIT)
        throw std::logic_error("readbackDepth: needs a single-sample D32_SFLOAT(_S8_UINT) image");
    const Buffer staging = copyToHost(ctx, image, 4);
    ImageR32 out{image.desc.width, image.desc.height, std::vector<float>(staging.size / 4)};
    std::memcpy(out.r.data(), staging.mapped, staging.size);
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
