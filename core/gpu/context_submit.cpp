// GpuContext's command buffers and submissions (context.cpp creates the instance and device):
// every submission carries the uploads queued since the last one (core/gpu/upload_queue.h).
#include "core/gpu/context.h"
#include "core/gpu/upload_queue.h"
#include "core/gpu/vk_check.h"

namespace tp {

void GpuContext::waitIdle() {
    std::unique_lock<std::mutex> lock = lockQueue();
    VK_CHECK(vkQueueWaitIdle(queue));
}

VkCommandBuffer GpuContext::allocateCommandBuffer() {
    VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    info.commandPool = commandPool;
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = 1;
    VkCommandBuffer cmd;
    VK_CHECK(vkAllocateCommandBuffers(device, &info, &cmd));
    return cmd;
}

void GpuContext::freeCommandBuffer(VkCommandBuffer cmd) {
    vkFreeCommandBuffers(device, commandPool, 1, &cmd);
}

void GpuContext::submitAndWait(VkCommandBuffer cmd, VkCommandBuffer after) {
    VkCommandBufferSubmitInfo infos[3];
    uint32_t count = 0;
    for (VkCommandBuffer c : {uploads_ ? uploads_->take() : VK_NULL_HANDLE, cmd, after}) {
        if (!c) continue;
        infos[count] = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
        infos[count++].commandBuffer = c;
    }
    VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submit.commandBufferInfoCount = count;
    submit.pCommandBufferInfos = infos;
    {
        std::unique_lock<std::mutex> lock = lockQueue();
        VK_CHECK(vkQueueSubmit2(queue, 1, &submit, fence_));
    }
    VK_CHECK(vkWaitForFences(device, 1, &fence_, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(device, 1, &fence_));
    if (uploads_) uploads_->completed();
}

bool GpuContext::queueUpload(const Buffer& dst, const void* data, VkDeviceSize size) {
    return uploads_ && uploads_->queue(dst, data, size);
}

void GpuContext::flushUploads() {
    if (uploads_ && !uploads_->empty()) submitAndWait(VK_NULL_HANDLE);
}

bool GpuContext::uploadsWrite(VkBuffer buffer) const {
    return uploads_ && uploads_->writes(buffer);
}

void GpuContext::submitAndWait(const std::function<void(VkCommandBuffer)>& record) {
    VkCommandBuffer cmd = allocateCommandBuffer();
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
    record(cmd);
    VK_CHECK(vkEndCommandBuffer(cmd));
    submitAndWait(cmd);
    freeCommandBuffer(cmd);
}

} // namespace tp
