// Offscreen: the same UI frames as the window, drawn into an image that screenshots read back.
#include <chrono>
#include <cstdio>
#include <thread>

#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include "core/gpu/context.h"
#include "core/gpu/readback.h"
#include "core/gpu/vk_check.h"
#include "core/util/clock.h"
#include "viewer/ui_renderer.h"
#include "viewer/view_loop.h"

namespace tp::view {
namespace {

// The offscreen colour target and its framebuffer, rebuilt when the surface size changes.
struct Target {
    Image image;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    VkExtent2D extent{0, 0};
    void resize(GpuContext& ctx, const UiRenderer& ui, uint32_t w, uint32_t h) {
        if (extent.width == w && extent.height == h) return;
        ctx.waitIdle();
        if (framebuffer) vkDestroyFramebuffer(ctx.device, framebuffer, nullptr);
        ImageDesc d;
        d.format = VK_FORMAT_R8G8B8A8_UNORM;
        d.width = w, d.height = h;
        d.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                  VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        image = createImage(ctx, d, {"viewer", "", "ui_target", "the offscreen UI frame"});
        extent = {w, h};
        framebuffer = ui.createFramebuffer(image.view, extent);
    }
    void destroy(GpuContext& ctx) {
        if (framebuffer) vkDestroyFramebuffer(ctx.device, framebuffer, nullptr);
        image.reset();
    }
};

} // namespace

int runHeadless(const LoopSetup& setup) {
    ContextOptions co = setup.viewer.context;
    co.queues = 2; // the renderers' own, where the device has one (--share-device)
    Result<std::unique_ptr<GpuContext>> created = GpuContext::create(co);
    if (!created) {
        std::fprintf(stderr, "triptych: %s\n", created.error().c_str());
        return 2;
    }
    GpuContext& ctx = **created;
    createImGuiContext();
    std::string scriptError;
    int code = 0;
    {
        UiRenderer ui(ctx, VK_FORMAT_R8G8B8A8_UNORM, 2, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        ViewerApp app(ctx, setup.viewer);
        app.setTargetBgra(ui.bgra());
        ScriptRunner runner(*setup.script, setup.scriptPath, setup.out, setup.waitLimitSeconds,
                            true);
        ScriptMouse mouse;
        Target target;
        ImGuiIO& io = ImGui::GetIO();
        VkCommandBuffer cmd = ctx.allocateCommandBuffer();
        try {
            while (!runner.done()) {
                runner.beforeFrame(app, mouse);
                auto start = std::chrono::steady_clock::now();
                uint32_t w = 0, h = 0;
                surfaceSize(app, w, h);
                target.resize(ctx, ui, w, h);
                io.DisplaySize = ImVec2(float(w), float(h));
                io.DeltaTime = 1.0f / 60.0f; // fixed: scripted frames are reproducible
                io.MousePos = ImVec2(mouse.x, mouse.y);
                io.MouseDown[0] = mouse.down;
                ImGui_ImplVulkan_NewFrame();
                ImGui::NewFrame();
                app.frame();
                ImGui::Render();
                if (app.takeSceneDirty()) ui.setScene(app.scene());
                VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
                VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
                ui.record(cmd, target.image.image, target.framebuffer, target.extent,
                          ImGui::GetDrawData());
                VK_CHECK(vkEndCommandBuffer(cmd));
                ctx.submitAndWait(cmd);
                std::optional<ImageRGBA> shot;
                if (runner.wantsScreenshot()) shot = readbackColor(ctx, target.image);
                double frameMs = msSince(start);
                runner.afterFrame(app, shot ? &*shot : nullptr, frameMs);
                // While the workers render on the CPU (lavapipe), leave it to them; a GPU's UI
                // frames go on at their own rate, as the window's do (window_loop.cpp).
                if (ctx.isCpuDevice() && !app.settled())
                    std::this_thread::sleep_for(std::chrono::milliseconds(10));
            }
        } catch (const ScriptError& e) {
            scriptError = e.what();
        }
        ctx.freeCommandBuffer(cmd);
        ctx.waitIdle();
        target.destroy(ctx);
        code = finish(app, ctx, scriptError);
    }
    ImGui::DestroyContext(); // after the UiRenderer's backend shutdown
    return code;
}

} // namespace tp::view
