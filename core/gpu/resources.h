#pragma once
// Buffers and images: the one place that allocates GPU memory, so the ledger is complete.
// Each resource gets its own VkDeviceMemory (dedicated allocation): at our resource counts
// that costs nothing measurable and makes each ledger line the driver's own number.
#include <cstdint>
#include <string>

#include <vulkan/vulkan.h>

#include "core/gpu/ledger.h"
#include "core/util/result.h"

namespace tp {

class GpuContext;

struct Buffer {
    GpuContext* ctx = nullptr;
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr; // host-visible buffers stay mapped
    uint64_t ledgerId = 0;

    Buffer() = default;
    Buffer(Buffer&& other) noexcept { *this = std::move(other); }
    Buffer& operator=(Buffer&& other) noexcept;
    Buffer(const Buffer&) = delete;
    ~Buffer() { reset(); }
    void reset();
};

struct ImageDesc {
    VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
    uint32_t width = 1, height = 1;
    uint32_t mipLevels = 1;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    VkImageUsageFlags usage = 0;
};

struct Image {
    GpuContext* ctx = nullptr;
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    ImageDesc desc;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    uint64_t ledgerId = 0;

    Image() = default;
    Image(Image&& other) noexcept { *this = std::move(other); }
    Image& operator=(Image&& other) noexcept;
    Image(const Image&) = delete;
    ~Image() { reset(); }
    void reset();
};

enum class MemoryKind { Device, Upload, Readback };

Buffer createBuffer(GpuContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryKind kind,
                    const LedgerTag& tag);
Image createImage(GpuContext& ctx, const ImageDesc& desc, const LedgerTag& tag);
// Whether the device can create `desc` (format, usage, size, sample count) as an optimal-tiled
// 2D image: one line naming what it lacks ("8 samples of R32G32B32A32_SFLOAT with storage use
// not supported by DEVICE"), for callers that must refuse instead of failing in vkCreateImage.
Status checkImageSupported(const GpuContext& ctx, const ImageDesc& desc);

// Device-local buffer filled from host memory through a staging buffer (staging is not
// kept, so it is not in the ledger).
Buffer createBufferWithData(GpuContext& ctx, const void* data, VkDeviceSize size,
                            VkBufferUsageFlags usage, const LedgerTag& tag);
// Overwrites the first `size` bytes of a device-local buffer (made with TRANSFER_DST) between
// frames: per-view data of a planned renderer. The copy is queued for the context's next
// submission (GpuContext::queueUpload, no wait of its own) unless it is large, when it goes
// through a staging buffer of its own and a wait. Either way every later submission sees it.
void uploadBufferData(GpuContext& ctx, const Buffer& dst, const void* data, VkDeviceSize size);

// Records the copy of `img`'s mip 0 from `staging` at `offset` and blits its mip chain down.
// Hand-written barriers: uploads happen outside the frame graph (textures, the viewer's images
// from the CPU). Ends in SHADER_READ_ONLY_OPTIMAL for every later submission.
void recordImageUpload(VkCommandBuffer cmd, const Image& img, VkBuffer staging, VkDeviceSize offset);

// Records the copy of a buffer of width x height tightly packed fp32 depths into the depth
// aspect of `image` (in TRANSFER_DST_OPTIMAL; mip 0, layer 0): how a compute rasterizer's
// depths become a D32 image that shaders sample and passes depth-test against (a shader cannot
// store to a depth image).
void recordDepthCopy(VkCommandBuffer cmd, VkBuffer depths, VkImage image, uint32_t width,
                     uint32_t height);

bool isDepthFormat(VkFormat format);
// A depth format with a stencil aspect too: its views and barriers name both aspects, its
// attachment layout is DEPTH_STENCIL_ATTACHMENT_OPTIMAL (attachmentLayout), a copy names depth.
bool hasStencil(VkFormat format);
// The layout a use's `layout` is for an image of `format`: DEPTH_ATTACHMENT_OPTIMAL may not
// name a stencil aspect, so a depth-stencil image is in DEPTH_STENCIL_ATTACHMENT_OPTIMAL.
VkImageLayout attachmentLayout(VkFormat format, VkImageLayout layout);

// A global memory barrier, for the few hand-written ones outside the frame graph (uploads,
// readbacks): each call site says why it needs one.
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

} // namespace tp
