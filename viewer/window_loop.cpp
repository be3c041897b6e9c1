// The window: GLFW for input and the surface, the swapchain, the same frame as headless.
#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <thread>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include "core/gpu/context.h"
#include "core/util/clock.h"
#include "viewer/keys.h"
#include "viewer/swapchain.h"
#include "viewer/ui_renderer.h"
#include "viewer/view_loop.h"

namespace tp::view {
namespace {

std::string glfwMessage;

void onGlfwError(int, const char* description) {
    glfwMessage = description ? description : "unknown error";
}

int noDisplay(const std::string& why) {
    std::fprintf(stderr,
                 "triptych: view: cannot open a window (%s): run it under an X server (e.g. "
                 "xvfb-run -a triptych view) or offscreen with --headless --script FILE\n",
                 why.c_str());
    return 2;
}

// Keys the viewer reads itself when ImGui does not want the keyboard: held ones (fly) every
// frame, the others once per press.
void pollKeys(GLFWwindow* window, ViewerApp& app, std::map<int, bool>& wasDown) {
    if (ImGui::GetIO().WantCaptureKeyboard) return;
    for (int key : {'F', 'R', ' ', '1', '2', '3', 'W', 'A', 'S', 'D', 'Q', 'E'}) {
        bool down = glfwGetKey(window, key) == GLFW_PRESS;
        if (down && (isHeldKey(key) || !wasDown[key])) applyKey(app, key);
        wasDown[key] = down;
    }
}

// Frames until the window closes (or --quit-after, once the script is done); the script's
// error, or empty.
std::string frameLoop(GLFWwindow* window, GpuContext& ctx, UiRenderer& ui, Swapchain& swapchain,
                      ViewerApp& app, const LoopSetup& setup) {
    std::optional<ScriptRunner> runner;
    if (setup.script)
        runner.emplace(*setup.script, setup.scriptPath, setup.out, setup.waitLimitSeconds, false);
    ScriptMouse scriptMouse; // the real cursor wins in a window
    std::map<int, bool> wasDown;
    try {
        for (int frame = 0; !glfwWindowShouldClose(window); ++frame) {
            glfwPollEvents();
            if (runner) runner->beforeFrame(app, scriptMouse);
            auto start = std::chrono::steady_clock::now();
            ImGui_ImplVulkan_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            pollKeys(window, app, wasDown);
            app.frame();
            ImGui::Render();
            if (app.takeSceneDirty()) ui.setScene(app.scene());
            int fw = 0, fh = 0;
            glfwGetFramebufferSize(window, &fw, &fh);
            swapchain.draw(ui, ImGui::GetDrawData(), uint32_t(fw), uint32_t(fh));
            // The frame's work, present included (FIFO: paced by the display where it has one).
            double frameMs = msSince(start);
            if (runner) runner->afterFrame(app, nullptr, frameMs);
            // On a CPU device the renders run on the same cores: leave them the CPU while they
            // work.
            if (ctx.isCpuDevice() && !app.settled())
                std::this_thread::sleep_for(std::chrono::milliseconds(10));
            bool scriptDone = !runner || runner->done();
            if (setup.quitAfterFrames > 0 && frame + 1 >= setup.quitAfterFrames && scriptDone)
                break;
        }
    } catch (const ScriptError& e) {
        return e.what();
    }
    return {};
}

// The viewer on a window surface the device presents to; the exit code.
int runInWindow(GLFWwindow* window, GpuContext& ctx, VkSurfaceKHR surface, const LoopSetup& setup) {
    VkFormat format = chooseSurfaceFormat(ctx, surface);
    UiRenderer ui(ctx, format, 3, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);
    Swapchain swapchain(ctx, surface, format, ui);
    ViewerApp app(ctx, setup.viewer);
    app.setTargetBgra(ui.bgra());
    uint32_t w0 = 0, h0 = 0;
    surfaceSize(app, w0, h0);
    glfwSetWindowSize(window, int(w0), int(h0));
    const std::string scriptError = frameLoop(window, ctx, ui, swapchain, app, setup);
    return finish(app, ctx, scriptError);
}

} // namespace

int runWindow(const LoopSetup& setup) {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) return noDisplay(glfwMessage);
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        return noDisplay("GLFW finds no Vulkan loader");
    }
    ContextOptions co = setup.viewer.context;
    co.queues = 2; // the renderers' own, where the device has one (--share-device)
    uint32_t n = 0;
    const char** extensions = glfwGetRequiredInstanceExtensions(&n);
    for (uint32_t i = 0; i < n; ++i)
        co.instanceExtensions.push_back(extensions[i]);
    co.swapchain = true;
    Result<std::unique_ptr<GpuContext>> created = GpuContext::create(co);
    if (!created) {
        glfwTerminate();
        std::fprintf(stderr, "triptych: %s\n", created.error().c_str());
        return 2;
    }
    GpuContext& ctx = **created;
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    GLFWwindow* window = glfwCreateWindow(1100, 560, "triptych view", nullptr, nullptr);
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    if (!window || glfwCreateWindowSurface(ctx.instance, window, nullptr, &surface) != VK_SUCCESS) {
        if (window) glfwDestroyWindow(window);
        glfwTerminate();
        return noDisplay(glfwMessage.empty() ? "no window surface" : glfwMessage);
    }
    VkBool32 presentable = VK_FALSE;
    vkGetPhysicalDeviceSurfaceSupportKHR(ctx.physical, ctx.queueFamily, surface, &presentable);
    int code = 0;
    createImGuiContext();
    ImGui_ImplGlfw_InitForVulkan(window, true);
    if (!presentable) {
        code = noDisplay(ctx.info.name + " cannot present to this window");
    } else
        try { // a Vulkan failure ends the window below with its cleanup, as one line (exit 4)
            code = runInWindow(window, ctx, surface, setup);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "triptych: view: %s\n", e.what());
            code = 4;
        }
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    vkDestroySurfaceKHR(ctx.instance, surface, nullptr);
    glfwDestroyWindow(window);
    glfwTerminate();
    return code;
}

} // namespace tp::view
