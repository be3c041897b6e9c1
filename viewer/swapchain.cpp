#include "viewer/swapchain.h"

#include <algorithm>

#include "core/gpu/context.h"
#include "core/gpu/vk_check.h"
#include "viewer/ui_renderer.h"

namespace tp::view {

VkFormat chooseSurfaceFormat(const GpuContext& ctx, VkSurfaceKHR surface) {
    uint32_t n = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(ctx.physical, surface, &n, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(n);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(ctx.physical, surface, &n, formats.data()));
    for (VkFormat want : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
        for (const VkSurfaceFormatKHR& f : formats)
            if (f.format == want && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return want;
    throw GpuError("the window surface offers no B8G8R8A8_UNORM or R8G8B8A8_UNORM format");
}

Swapchain::Swapchain(GpuContext& ctx, VkSurfaceKHR surface, VkFormat format, const UiRenderer& ui)
    : ctx_(ctx), surface_(surface), format_(format), ui_(ui) {
    VkSemaphoreCreateInfo si{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VK_CHECK(vkCreateSemaphore(ctx.device, &si, nullptr, &acquired_));
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(ctx.device, &fi, nullptr, &fence_));
    cmd_ = ctx.allocateCommandBuffer();
}

Swapchain::~Swapchain() {
    ctx_.waitIdle();
    destroy();
    ctx_.freeCommandBuffer(cmd_);
    vkDestroyFence(ctx_.device, fence_, nullptr);
    vkDestroySemaphore(ctx_.device, acquired_, nullptr);
}

void Swapchain::destroy() {
    for (VkFramebuffer fb : framebuffers_)
        vkDestroyFramebuffer(ctx_.device, fb, nullptr);
    for (VkImageView v : views_)
        vkDestroyImageView(ctx_.device, v, nullptr);
    for (VkSemaphore s : renderDone_)
        vkDestroySemaphore(ctx_.device, s, nullptr);
    framebuffers_.clear(), views_.clear(), renderDone_.clear(), images_.clear();
    if (swapchain_) vkDestroySwapchainKHR(ctx_.device, swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
}

void Swapchain::create(uint32_t width, uint32_t height) {
    ctx_.waitIdle();
    destroy();
    requested_ = {width, height};
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_.physical, surface_, &caps));
    extent_ = caps.currentExtent.width != UINT32_MAX
                  ? caps.currentExtent
                  : VkExtent2D{
                        std::clamp(width, caps.minImageExtent.width, caps.maxImageExtent.width),
                        std::clamp(height, caps.minImageExtent.height, caps.maxImageExtent.height)};
    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface_;
    info.minImageCount = caps.maxImageCount ? std::min(caps.minImageCount + 1, caps.maxImageCount)
                                            : caps.minImageCount + 1;
    info.imageFormat = format_;
    info.imageColorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    // TRANSFER_DST: the scene area is copied in before ImGui draws over it.
    info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR; // always available; paces the UI to the display
    info.clipped = VK_TRUE;
    VK_CHECK(vkCreateSwapchainKHR(ctx_.device, &info, nullptr, &swapchain_));
    uint32_t n = 0;
    VK_CHECK(vkGetSwapchainImagesKHR(ctx_.device, swapchain_, &n, nullptr));
    images_.resize(n);
    VK_CHECK(vkGetSwapchainImagesKHR(ctx_.device, swapchain_, &n, images_.data()));
    for (VkImage image : images_) {
        VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        vi.image = image;
        vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vi.format = format_;
        vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView view;
        VK_CHECK(vkCreateImageView(ctx_.device, &vi, nullptr, &view));
        views_.push_back(view);
        framebuffers_.push_back(ui_.createFramebuffer(view, extent_));
        VkSemaphoreCreateInfo si{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        VkSemaphore s;
        VK_CHECK(vkCreateSemaphore(ctx_.device, &si, nullptr, &s));
        renderDone_.push_back(s);
    }
    stale_ = false;
}

void Swapchain::draw(UiRenderer& ui, ImDrawData* data, uint32_t width, uint32_t height) {
    if (width == 0 || height == 0) return; // minimised
    if (!swapchain_ || stale_ || width != requested_.width || height != requested_.height)
        create(width, height);
    uint32_t index = 0;
    VkResult r = vkAcquireNextImageKHR(ctx_.device, swapchain_, UINT64_MAX, acquired_,
                                       VK_NULL_HANDLE, &index);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
        stale_ = true;
        return;
    }
    if (r != VK_SUBOPTIMAL_KHR) VK_CHECK(r);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    VK_CHECK(vkBeginCommandBuffer(cmd_, &begin));
    ui.record(cmd_, images_[index], framebuffers_[index], extent_, data);
    VK_CHECK(vkEndCommandBuffer(cmd_));
    VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    wait.semaphore = acquired_;
    wait.stageMask =
        VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT; // the first use is a transfer (the clear)
    VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    signal.semaphore = renderDone_[index];
    signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cmdInfo.commandBuffer = cmd_;
    VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submit.waitSemaphoreInfoCount = 1;
    submit.pWaitSemaphoreInfos = &wait;
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &cmdInfo;
    submit.signalSemaphoreInfoCount = 1;
    submit.pSignalSemaphoreInfos = &signal;
    ctx_.flushUploads(); // this submission is not the context's: what it queued goes first
    std::unique_lock<std::mutex> queue = ctx_.lockQueue(); // shared with the renderers on lavapipe
    VK_CHECK(vkQueueSubmit2(ctx_.queue, 1, &submit, fence_));
    VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &renderDone_[index];
    present.swapchainCount = 1;
    present.pSwapchains = &swapchain_;
    present.pImageIndices = &index;
    r = vkQueuePresentKHR(ctx_.queue, &present);
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR)
        stale_ = true;
    else
        VK_CHECK(r);
    queue.unlock();
    // One frame at a time: the command buffer, the acquire semaphore and ImGui's buffers are
    // reused.
    VK_CHECK(vkWaitForFences(ctx_.device, 1, &fence_, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(ctx_.device, 1, &fence_));
}

} // namespace tp::view
