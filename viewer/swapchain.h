#pragma once
// The window's swapchain: images the UiRenderer draws into (TRANSFER_DST for the scene area),
// one framebuffer each, and the acquire/present handshake. One frame at a time: each present
// waits for its frame's fence, so the UI's buffers are never in use twice.
#include <vector>

#include <vulkan/vulkan.h>

struct ImDrawData;

namespace tp {
class GpuContext;
}

namespace tp::view {

class UiRenderer;

// A B8G8R8A8 or R8G8B8A8 UNORM format the surface offers (the UI's colours are display values).
VkFormat chooseSurfaceFormat(const GpuContext& ctx, VkSurfaceKHR surface);

class Swapchain {
  public:
    Swapchain(GpuContext& ctx, VkSurfaceKHR surface, VkFormat format, const UiRenderer& ui);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;
    // Draws and presents one frame at the window's framebuffer size (recreated when it changed).
    void draw(UiRenderer& ui, ImDrawData* data, uint32_t width, uint32_t height);

  private:
    void create(uint32_t width, uint32_t height);
    void destroy();

    GpuContext& ctx_;
    VkSurfaceKHR surface_;
    VkFormat format_;
    const UiRenderer& ui_;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkExtent2D extent_{0, 0};
    // The framebuffer size the swapchain was last made for: the surface may clamp or fix
    // extent_ to something else, which must not make every frame rebuild the swapchain.
    VkExtent2D requested_{0, 0};
    std::vector<VkImage> images_;
    std::vector<VkImageView> views_;
    std::vector<VkFramebuffer> framebuffers_;
    std::vector<VkSemaphore> renderDone_; // per image: present waits on it
    VkSemaphore acquired_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    bool stale_ = false;
};

} // namespace tp::view
