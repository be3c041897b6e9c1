#include "core/gpu/upload_queue.h"

#include <algorithm>
#include <cstring>

#include "core/gpu/context.h"
#include "core/gpu/vk_check.h"

namespace tp {
namespace {

constexpr VkDeviceSize kMinRingBytes = VkDeviceSize(64) << 10;
constexpr VkDeviceSize kAlign = 16;

VkDeviceSize alignUp(VkDeviceSize v) {
    return (v + kAlign - 1) / kAlign * kAlign;
}

} // namespace

UploadQueue::~UploadQueue() {
    if (cmd_) ctx_.freeCommandBuffer(cmd_);
}

void UploadQueue::begin() {
    if (!cmd_) cmd_ = ctx_.allocateCommandBuffer();
    VK_CHECK(vkResetCommandBuffer(cmd_, 0));
    VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd_, &info));
    open_ = true;
}

bool UploadQueue::queue(const Buffer& dst, const void* data, VkDeviceSize size) {
    if (size >= kMaxQueuedBytes || taken_) return false;
    if (used_ + alignUp(size) > ring_.size) {
        if (!empty()) ctx_.flushUploads(); // the ring is free again after it
        if (alignUp(size) > ring_.size) {
            ring_ = {};
            ring_ = createBuffer(ctx_, std::max({kMinRingBytes, 2 * ring_.size, alignUp(size)}),
                                 VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::Upload,
                                 {"staging", "", "upload_queue",
                                  "uploads queued for the next submission"});
        }
    }
    if (!open_) begin();
    if (writes(dst.buffer)) // written twice before a submission (lights set, then moved): in order
        memoryBarrier(cmd_, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    std::memcpy(static_cast<uint8_t*>(ring_.mapped) + used_, data, size);
    VkBufferCopy copy{used_, 0, size};
    vkCmdCopyBuffer(cmd_, ring_.buffer, dst.buffer, 1, &copy);
    used_ += alignUp(size);
    targets_.push_back(dst.buffer);
    return true;
}

VkCommandBuffer UploadQueue::take() {
    if (!open_) return VK_NULL_HANDLE;
    // Hand-written barrier (the exception to graph-derived ones): the uploads happen outside
    // any frame graph; its second scope covers every command after it in the batch, and every
    // later submission.
    memoryBarrier(cmd_, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                  VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
    VK_CHECK(vkEndCommandBuffer(cmd_));
    open_ = false;
    taken_ = true;
    return cmd_;
}

void UploadQueue::completed() {
    if (!taken_) return;
    taken_ = false;
    used_ = 0;
    targets_.clear();
}

bool UploadQueue::writes(VkBuffer buffer) const {
    return std::find(targets_.begin(), targets_.end(), buffer) != targets_.end();
}

} // namespace tp
