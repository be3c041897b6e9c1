#include "core/gpu/resources.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "core/gpu/barriers.h"
#include "core/gpu/context.h"
#include "core/gpu/vk_check.h"

namespace tp {
namespace {

uint32_t findMemoryType(const GpuContext& ctx, uint32_t bits, VkMemoryPropertyFlags want) {
    const VkPhysicalDeviceMemoryProperties& mp = ctx.memoryProperties;
    for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
        if ((bits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) return i;
    throw GpuError("no Vulkan memory type with the required properties");
}

VkMemoryPropertyFlags memoryFlags(MemoryKind kind) {
    switch (kind) {
    case MemoryKind::Device:
        return VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    case MemoryKind::Upload:
        return VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    case MemoryKind::Readback:
        return VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    }
    return 0;
}

VkDeviceMemory allocate(GpuContext& ctx, const VkMemoryRequirements& req,
                        VkMemoryPropertyFlags flags) {
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = req.size;
    info.memoryTypeIndex = findMemoryType(ctx, req.memoryTypeBits, flags);
    VkDeviceMemory memory;
    VK_CHECK(vkAllocateMemory(ctx.device, &info, nullptr, &memory));
    return memory;
}

} // namespace

bool hasStencil(VkFormat format) {
    return format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

VkImageLayout attachmentLayout(VkFormat format, VkImageLayout layout) {
    return hasStencil(format) && layout == VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL
               ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL
               : layout;
}

bool isDepthFormat(VkFormat format) {
    return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM ||
           format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    barrier.srcStageMask = srcStage;
    barrier.srcAccessMask = srcAccess;
    barrier.dstStageMask = dstStage;
    barrier.dstAccessMask = dstAccess;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd, &dep);
}

Buffer& Buffer::operator=(Buffer&& o) noexcept {
    if (this != &o) {
        reset();
        ctx = std::exchange(o.ctx, nullptr);
        buffer = std::exchange(o.buffer, VK_NULL_HANDLE);
        memory = std::exchange(o.memory, VK_NULL_HANDLE);
        size = std::exchange(o.size, 0);
        mapped = std::exchange(o.mapped, nullptr);
        ledgerId = std::exchange(o.ledgerId, 0);
    }
    return *this;
}

void Buffer::reset() {
    if (!ctx) return;
    if (ctx->uploadsWrite(buffer)) ctx->flushUploads(); // a queued copy still writes it
    vkDestroyBuffer(ctx->device, buffer, nullptr);
    vkFreeMemory(ctx->device, memory, nullptr);
    ctx->ledger.remove(ledgerId);
    ctx = nullptr;
    buffer = VK_NULL_HANDLE;
    memory = VK_NULL_HANDLE;
    mapped = nullptr;
}

Image& Image::operator=(Image&& o) noexcept {
    if (this != &o) {
        reset();
        ctx = std::exchange(o.ctx, nullptr);
        image = std::exchange(o.image, VK_NULL_HANDLE);
        view = std::exchange(o.view, VK_NULL_HANDLE);
        memory = std::exchange(o.memory, VK_NULL_HANDLE);
        desc = o.desc;
        aspect = o.aspect;
        ledgerId = std::exchange(o.ledgerId, 0);
    }
    return *this;
}

void Image::reset() {
    if (!ctx) return;
    if (view) vkDestroyImageView(ctx->device, view, nullptr);
    vkDestroyImage(ctx->device, image, nullptr);
    vkFreeMemory(ctx->device, memory, nullptr);
    ctx->ledger.remove(ledgerId);
    ctx = nullptr;
    image = VK_NULL_HANDLE;
    view = VK_NULL_HANDLE;
    memory = VK_NULL_HANDLE;
}

Buffer createBuffer(GpuContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryKind kind,
                    const LedgerTag& tag) {
    Buffer b;
    b.ctx = &ctx;
    b.size = size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size > 0 ? size : 4; // a zero-sized buffer is invalid; keep bindings valid
    info.usage = usage;
    VK_CHECK(vkCreateBuffer(ctx.device, &info, nullptr, &b.buffer));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(ctx.device, b.buffer, &req);
    b.memory = allocate(ctx, req, memoryFlags(kind));
    VK_CHECK(vkBindBufferMemory(ctx.device, b.buffer, b.memory, 0));
    if (kind != MemoryKind::Device)
        VK_CHECK(vkMapMemory(ctx.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped));
    LedgerEntry e;
    e.tag = tag;
    e.requestedBytes = size;
    e.bytes = req.size;
    b.ledgerId = ctx.ledger.add(e);
    return b;
}

namespace {

std::string usageNames(VkImageUsageFlags usage) {
    static const std::pair<VkImageUsageFlagBits, const char*> names[] = {
        {VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "transfer-src"},
        {VK_IMAGE_USAGE_TRANSFER_DST_BIT, "transfer-dst"},
        {VK_IMAGE_USAGE_SAMPLED_BIT, "sampled"},
        {VK_IMAGE_USAGE_STORAGE_BIT, "storage"},
        {VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, "colour attachment"},
        {VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, "depth attachment"},
        {VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT, "input attachment"}};
    std::string out;
    for (const auto& [bit, name] : names)
        if (usage & bit) {
            if (!out.empty()) out += '+';
            out += name;
        }
    return out;
}

} // namespace

Status checkImageSupported(const GpuContext& ctx, const ImageDesc& desc) {
    VkImageFormatProperties props{};
    VkResult r =
        vkGetPhysicalDeviceImageFormatProperties(ctx.physical, desc.format, VK_IMAGE_TYPE_2D,
                                                 VK_IMAGE_TILING_OPTIMAL, desc.usage, 0, &props);
    const std::string what =
        std::string(formatName(desc.format)) + " with " + usageNames(desc.usage) + " use";
    if (r != VK_SUCCESS) return Error{what + ": not supported by " + ctx.info.name};
    if (!(props.sampleCounts & desc.samples))
        return Error{std::to_string(uint32_t(desc.samples)) + " samples of " + what +
                     ": not supported by " + ctx.info.name};
    if (desc.width > props.maxExtent.width || desc.height > props.maxExtent.height ||
        desc.mipLevels > props.maxMipLevels)
        return Error{std::to_string(desc.width) + "x" + std::to_string(desc.height) + " " + what +
                     ": larger than " + ctx.info.name + " allows (" +
                     std::to_string(props.maxExtent.width) + "x" +
                     std::to_string(props.maxExtent.height) + ")"};
    return {};
}

Image createImage(GpuContext& ctx, const ImageDesc& desc, const LedgerTag& tag) {
    Image img;
    img.ctx = &ctx;
    img.desc = desc;
    img.aspect = !isDepthFormat(desc.format) ? VK_IMAGE_ASPECT_COLOR_BIT
                 : hasStencil(desc.format)   ? VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT
                                             : VK_IMAGE_ASPECT_DEPTH_BIT;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = desc.format;
    info.extent = {desc.width, desc.height, 1};
    info.mipLevels = desc.mipLevels;
    info.arrayLayers = 1;
    info.samples = desc.samples;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = desc.usage;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VK_CHECK(vkCreateImage(ctx.device, &info, nullptr, &img.image));
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(ctx.device, img.image, &req);
    img.memory = allocate(ctx, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK_CHECK(vkBindImageMemory(ctx.device, img.image, img.memory, 0));
    // A view needs a usage that views serve; an image only copied to/from gets none.
    const VkImageUsageFlags viewUsages = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                         VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                         VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    if (desc.usage & viewUsages) {
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = img.image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = desc.format;
        view.subresourceRange = {img.aspect, 0, desc.mipLevels, 0, 1};
        VK_CHECK(vkCreateImageView(ctx.device, &view, nullptr, &img.view));
    }
    LedgerEntry e;
    e.tag = tag;
    e.isImage = true;
    e.format = desc.format;
    e.width = desc.width;
    e.height = desc.height;
    e.mipLevels = desc.mipLevels;
    e.samples = uint32_t(desc.samples);
    e.requestedBytes =
        uint64_t(desc.width) * desc.height * desc.samples * formatBytesPerTexel(desc.format);
    e.bytes = req.size;
    img.ledgerId = ctx.ledger.add(e);
    return img;
}

Buffer createBufferWithData(GpuContext& ctx, const void* data, VkDeviceSize size,
                            VkBufferUsageFlags usage, const LedgerTag& tag) {
    Buffer dst =
        createBuffer(ctx, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::Device, tag);
    uploadBufferData(ctx, dst, data, size);
    return dst;
}

void uploadBufferData(GpuContext& ctx, const Buffer& dst, const void* data, VkDeviceSize size) {
    if (size == 0 || ctx.queueUpload(dst, data, size)) return;
    Buffer staging = createBuffer(ctx, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::Upload,
                                  {"staging", "", "staging", "upload"});
    std::memcpy(staging.mapped, data, size);
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferCopy copy{0, 0, size};
        vkCmdCopyBuffer(cmd, staging.buffer, dst.buffer, 1, &copy);
        // Hand-written barrier (the exception to graph-derived ones): the upload happens
        // outside any frame graph, between frames; its second scope covers every later
        // submission.
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
    });
}

namespace {

// Mips [mip, mip + mips) of a colour image's one layer.
VkImageSubresourceRange mipRange(uint32_t mip, uint32_t mips) {
    return {VK_IMAGE_ASPECT_COLOR_BIT, mip, mips, 0, 1};
}

} // namespace

void recordDepthCopy(VkCommandBuffer cmd, VkBuffer depths, VkImage image, uint32_t width,
                     uint32_t height) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
    region.imageExtent = {width, height, 1};
    vkCmdCopyBufferToImage(cmd, depths, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
}

void recordImageUpload(VkCommandBuffer cmd, const Image& img, VkBuffer staging,
                         VkDeviceSize offset) {
    const uint32_t mips = img.desc.mipLevels;
    const VkPipelineStageFlags2 T = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
    imageBarrier(cmd, img.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_PIPELINE_STAGE_2_NONE, 0, T, VK_ACCESS_2_TRANSFER_WRITE_BIT, mipRange(0, mips));
    VkBufferImageCopy region{};
    region.bufferOffset = offset;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {img.desc.width, img.desc.height, 1};
    vkCmdCopyBufferToImage(cmd, staging, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                           &region);
    int32_t w = int32_t(img.desc.width), h = int32_t(img.desc.height);
    for (uint32_t m = 1; m < mips; ++m) {
        imageBarrier(cmd, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, T, VK_ACCESS_2_TRANSFER_WRITE_BIT, T,
                     VK_ACCESS_2_TRANSFER_READ_BIT, mipRange(m - 1, 1));
        VkImageBlit blit{};
        blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, m - 1, 0, 1};
        blit.srcOffsets[1] = {w, h, 1};
        w = std::max(1, w / 2);
        h = std::max(1, h / 2);
        blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, m, 0, 1};
        blit.dstOffsets[1] = {w, h, 1};
        vkCmdBlitImage(cmd, img.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, img.image,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
    }
    const VkPipelineStageFlags2 S = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    if (mips > 1)
        imageBarrier(cmd, img.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, T, 0, S,
                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, mipRange(0, mips - 1));
    imageBarrier(cmd, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, T, VK_ACCESS_2_TRANSFER_WRITE_BIT, S,
                 VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, mipRange(mips - 1, 1));
}


} // namespace tp
