#pragma once
// Buffer uploads queued for the context's next submission instead of a submission and a wait
// of their own (issue 42: on the H200 each wait cost about a millisecond, and a new view in the
// viewer made several: the lights, the culling parameters, the binning inputs). The bytes are
// copied at once into a staging ring the context keeps; the copies are recorded into a command
// buffer that GpuContext::submitAndWait puts first in the batch of whatever it submits next,
// closed by a barrier that makes them visible to every later command. Large uploads (scene
// loading) keep the direct path: holding them would hold their staging memory.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/resources.h"

namespace tp {

class GpuContext;

class UploadQueue {
  public:
    // An upload this large or larger goes through a staging buffer and a wait of its own.
    static constexpr VkDeviceSize kMaxQueuedBytes = VkDeviceSize(4) << 20;

    explicit UploadQueue(GpuContext& ctx) : ctx_(ctx) {}
    ~UploadQueue();
    UploadQueue(const UploadQueue&) = delete;
    UploadQueue& operator=(const UploadQueue&) = delete;

    // Copies `data` now; false when it is too large to queue (the caller uploads directly).
    bool queue(const Buffer& dst, const void* data, VkDeviceSize size);
    // The queued copies' command buffer, closed, for the next submission (VK_NULL_HANDLE when
    // nothing is queued); once that submission has completed, completed() frees the ring.
    VkCommandBuffer take();
    void completed();
    // Whether a queued copy writes `buffer` (a buffer about to be destroyed flushes first).
    bool writes(VkBuffer buffer) const;
    bool empty() const { return targets_.empty(); }

  private:
    void begin();
    GpuContext& ctx_;
    Buffer ring_;
    VkDeviceSize used_ = 0;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    bool open_ = false;    // cmd_ is recording
    bool taken_ = false;   // cmd_ is in a submission not yet completed
    std::vector<VkBuffer> targets_;
};

} // namespace tp
