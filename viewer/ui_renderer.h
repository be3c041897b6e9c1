#pragma once
// Draws one viewer frame into a colour image (the offscreen target or a swapchain image):
// the composed scene area copied in at the top-left, then Dear ImGui's draw data over it in
// one render pass. The ImGui Vulkan backend (Debian's libimgui-dev 1.86 sources, unmodified)
// is set up here, and only here, for that render pass.
#include <vulkan/vulkan.h>

#include "core/gpu/resources.h"
#include "viewer/composite.h"

struct ImDrawData;

namespace tp {
class GpuContext;
}

namespace tp::view {

class UiRenderer {
  public:
    // format: the target's (R8G8B8A8_UNORM offscreen, B8G8R8A8_UNORM for most swapchains).
    // finalLayout: where record() leaves the image (TRANSFER_SRC_OPTIMAL or PRESENT_SRC_KHR).
    UiRenderer(GpuContext& ctx, VkFormat format, uint32_t imageCount, VkImageLayout finalLayout);
    ~UiRenderer();
    UiRenderer(const UiRenderer&) = delete;
    UiRenderer& operator=(const UiRenderer&) = delete;

    VkRenderPass renderPass() const { return renderPass_; }
    VkFramebuffer createFramebuffer(VkImageView view, VkExtent2D extent) const;
    // Stages the scene area's bytes for the next record() (converted to the target's order),
    // or, composed on the GPU, copies them from scene.gpuBytes in each record().
    void setScene(const Composite& scene);
    // The target's channel order is BGRA (what a GPU composite must write).
    bool bgra() const {
        return format_ == VK_FORMAT_B8G8R8A8_UNORM || format_ == VK_FORMAT_B8G8R8A8_SRGB;
    }
    // The image may hold anything (UNDEFINED): it is cleared first. Leaves it in finalLayout.
    void record(VkCommandBuffer cmd, VkImage image, VkFramebuffer framebuffer, VkExtent2D extent,
                ImDrawData* drawData);

  private:
    GpuContext& ctx_;
    VkFormat format_;
    VkImageLayout finalLayout_;
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    Buffer staging_;
    VkBuffer source_ = VK_NULL_HANDLE; // staging_ or the GPU composite's bytes
    uint32_t sceneWidth_ = 0, sceneHeight_ = 0;
};

} // namespace tp::view
