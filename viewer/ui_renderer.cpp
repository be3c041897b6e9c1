#include "viewer/ui_renderer.h"

#include <algorithm>
#include <cstring>

#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include "core/gpu/barriers.h"
#include "core/gpu/context.h"
#include "core/gpu/vk_check.h"

namespace tp::view {
namespace {

// The backend's own error hook: the project's VK_CHECK (one line naming the result).
void checkVk(VkResult r) {
    if (r != VK_SUCCESS) VK_CHECK(r);
}

VkRenderPass createRenderPass(VkDevice device, VkFormat format) {
    // LOAD: the scene area and the clear were written by transfers before the pass; the
    // barriers around the pass are explicit in record(), so the layouts stay COLOR_ATTACHMENT.
    VkAttachmentDescription color{};
    color.format = format;
    color.samples = VK_SAMPLE_COUNT_1_BIT;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &ref;
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 1;
    info.pAttachments = &color;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    VkRenderPass pass;
    VK_CHECK(vkCreateRenderPass(device, &info, nullptr, &pass));
    return pass;
}

VkDescriptorPool createPool(VkDevice device) {
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
    VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    info.maxSets = 4;
    info.poolSizeCount = 1;
    info.pPoolSizes = &size;
    VkDescriptorPool pool;
    VK_CHECK(vkCreateDescriptorPool(device, &info, nullptr, &pool));
    return pool;
}

} // namespace

UiRenderer::UiRenderer(GpuContext& ctx, VkFormat format, uint32_t imageCount,
                       VkImageLayout finalLayout)
    : ctx_(ctx), format_(format), finalLayout_(finalLayout) {
    renderPass_ = createRenderPass(ctx.device, format);
    pool_ = createPool(ctx.device);
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = ctx.instance;
    info.PhysicalDevice = ctx.physical;
    info.Device = ctx.device;
    info.QueueFamily = ctx.queueFamily;
    info.Queue = ctx.queue;
    info.DescriptorPool = pool_;
    info.MinImageCount = std::max(2u, imageCount);
    info.ImageCount = std::max(2u, imageCount);
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = checkVk;
    ImGui_ImplVulkan_Init(&info, renderPass_);
    ctx.submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

UiRenderer::~UiRenderer() {
    ctx_.waitIdle();
    ImGui_ImplVulkan_Shutdown();
    staging_.reset();
    vkDestroyDescriptorPool(ctx_.device, pool_, nullptr);
    vkDestroyRenderPass(ctx_.device, renderPass_, nullptr);
}

VkFramebuffer UiRenderer::createFramebuffer(VkImageView view, VkExtent2D extent) const {
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass_;
    info.attachmentCount = 1;
    info.pAttachments = &view;
    info.width = extent.width;
    info.height = extent.height;
    info.layers = 1;
    VkFramebuffer fb;
    VK_CHECK(vkCreateFramebuffer(ctx_.device, &info, nullptr, &fb));
    return fb;
}

void UiRenderer::setScene(const Composite& scene) {
    VkDeviceSize size = VkDeviceSize(scene.width) * scene.height * 4;
    if (size == 0) {
        sceneWidth_ = sceneHeight_ = 0;
        return;
    }
    sceneWidth_ = scene.width;
    sceneHeight_ = scene.height;
    if (scene.gpuBytes) {
        source_ = scene.gpuBytes;
        return;
    }
    if (staging_.size < size)
        staging_ = createBuffer(
            ctx_, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::Upload,
            {"viewer", "", "scene_area", "the composed scene area, copied into each UI frame"});
    std::memcpy(staging_.mapped, scene.rgba.data(), size);
    if (bgra()) {
        auto* p = static_cast<uint8_t*>(staging_.mapped);
        for (VkDeviceSize i = 0; i < size; i += 4)
            std::swap(p[i], p[i + 2]);
    }
    source_ = staging_.buffer;
}

void UiRenderer::record(VkCommandBuffer cmd, VkImage image, VkFramebuffer framebuffer,
                        VkExtent2D extent, ImDrawData* drawData) {
    // ALL_COMMANDS as the first scope: it chains with a swapchain acquire's semaphore wait.
    imageBarrier(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                 VK_ACCESS_2_TRANSFER_WRITE_BIT);
    VkClearColorValue grey{{0.09f, 0.09f, 0.1f, 1.0f}};
    VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &grey, 1, &range);
    if (sceneWidth_ && sceneHeight_) {
        // The clear and the copy both write: the copy must land after the clear.
        imageBarrier(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkBufferImageCopy region{};
        region.bufferRowLength = sceneWidth_; // the scene may be wider than the window: clipped
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {std::min(sceneWidth_, extent.width),
                              std::min(sceneHeight_, extent.height), 1};
        vkCmdCopyBufferToImage(cmd, source_, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                               &region);
    }
    imageBarrier(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                 VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                 VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = renderPass_;
    begin.framebuffer = framebuffer;
    begin.renderArea.extent = extent;
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    ImGui_ImplVulkan_RenderDrawData(drawData, cmd);
    vkCmdEndRenderPass(cmd);
    const bool present = finalLayout_ == VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    // Present needs no access of ours (the semaphore orders it); a readback copies next.
    imageBarrier(cmd, image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, finalLayout_,
                 VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                 VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                 present ? VK_PIPELINE_STAGE_2_NONE : VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                 present ? VK_ACCESS_2_NONE : VK_ACCESS_2_TRANSFER_READ_BIT);
}

} // namespace tp::view
