#pragma once
// Headless Vulkan 1.3 context: instance (optionally with validation + synchronization
// validation), one physical device, one graphics+compute queue, a command pool, and the
// memory ledger every allocation goes through. No window of its own; the viewer asks for the
// instance extensions and the swapchain extension it needs (ContextOptions).
#include <array>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/ledger.h"
#include "core/util/result.h"

namespace tp {

class UploadQueue;
struct Buffer;

struct DeviceInfo {
    uint32_t index = 0;
    std::string name;
    std::string type; // "discrete", "integrated", "virtual", "cpu", "other"
    std::string driver;
    uint32_t apiVersion = 0;
    uint32_t vendorId = 0;         // PCI vendor (0x10de: NVIDIA)
    std::array<uint8_t, 16> uuid{}; // VkPhysicalDeviceIDProperties::deviceUUID: NVML's GPU UUID on NVIDIA
};

struct ContextOptions {
    bool validate = false; // Khronos validation + synchronization validation
    std::string
        device; // "" = best (discrete > integrated > virtual > cpu), an index, or a name substring
    // For a window (the viewer): the surface extensions GLFW asks for, and VK_KHR_swapchain
    // on the device. Empty/false: a headless context, as every other command uses.
    std::vector<std::string> instanceExtensions;
    bool swapchain = false;
    // Queues to create in the chosen family, as many as it has up to this (the viewer asks for
    // 2: its UI and its renderers, each submitting on its own queue of one device; share()).
    uint32_t queues = 1;
};

struct DeviceCaps {
    bool float64 = false;
    bool sampleRateShading = false;
    bool pipelineStatisticsQuery = false; // fragment-shader invocation counts (frame_runner)
    bool storageImageMultisample = false;
    bool fragmentStoresAndAtomics = false;
    uint32_t colorSampleCounts = 1; // VkSampleCountFlags supported for colour and depth
    float timestampPeriodNs = 1.0f;
    uint32_t timestampValidBits = 64;
    uint32_t maxImageDimension2D = 0;
    uint64_t maxStorageBufferRange = 0;
    uint32_t maxComputeSharedMemorySize = 0;
    uint32_t subgroupSize = 0;
    uint32_t subgroupStages = 0; // VkShaderStageFlags with subgroup operations
    uint32_t subgroupOps = 0;    // VkSubgroupFeatureFlags
    // A compute pipeline can require full subgroups of subgroupSize lanes (Vulkan 1.3's
    // subgroupSizeControl + computeFullSubgroups, with compute in requiredSubgroupSizeStages):
    // what a workgroup-is-one-subgroup shader needs (createComputePipeline's fullSubgroups).
    bool computeFullSubgroups = false;
    bool standardSampleLocations = false; // MSAA samples sit at the spec's standard locations
    // The visibility buffer's raster pass writes gl_PrimitiveID from a fragment shader (SPIR-V
    // needs the Geometry capability for it).
    bool geometryShader = false;
    // Culled meshlets are drawn with vkCmdDrawIndexedIndirectCount, many draws per call
    // (Vulkan 1.2's drawIndirectCount, 1.0's multiDrawIndirect): core/passes/meshlet_cull.h.
    bool drawIndirectCount = false;
    // Indirect draws with a firstInstance other than 0 (1.0's drawIndirectFirstInstance): the
    // visibility pass's culled draws carry each meshlet's first triangle in it.
    bool drawIndirectFirstInstance = false;
    // Dual-source blending (1.0's dualSrcBlend): multipass forward's blended light draws and
    // their transmittance resets as one pipeline (--light-draws gpu; blended_light_draw_pass.h).
    bool dualSrcBlend = false;
    // 64-bit integer atomics on storage buffers (shaderInt64 and Vulkan 1.2's
    // shaderBufferInt64Atomics): the visibility buffer's compute rasterizer (--vis-raster).
    bool int64Atomics = false;
};

class GpuContext {
  public:
    static Result<std::unique_ptr<GpuContext>> create(const ContextOptions& options);
    static Result<std::vector<DeviceInfo>> listDevices();
    // A second context on `owner`'s device (the viewer's renderers beside its UI): the same
    // instance, device, caps and info, its own command pool, fence and ledger, and the owner's
    // queue `queueIndex` when the owner created that many, else the owner's queue shared under
    // one lock. The owner must outlive it; its validation messages reach the owner.
    static std::unique_ptr<GpuContext> share(GpuContext& owner, uint32_t queueIndex);
    ~GpuContext();
    GpuContext(const GpuContext&) = delete;
    GpuContext& operator=(const GpuContext&) = delete;

    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memoryProperties{};
    DeviceCaps caps;
    DeviceInfo info;
    bool isCpuDevice() const { return properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }
    // Whether a fragment shader may reduce its lanes' values per subgroup, helpers left out
    // (gl_HelperInvocation), before an atomic: a GPU whose fragment stage has the basic, ballot
    // and arithmetic subgroup operations. Not a CPU device: slower there than one atomic per
    // fragment, and lavapipe (Mesa 22.3) cannot compile gl_HelperInvocation. The blended depth
    // bounds and multipass forward's light count ask it.
    bool reducesFragmentsBySubgroup() const;
    MemoryLedger ledger;

    // Records with `record`, submits, waits. For uploads, readbacks and timed frames. Every
    // submission carries the uploads queued since the last one first (queueUpload); `after`
    // goes in the same batch after `cmd` (the viewer's display copy after a view's last frame).
    void submitAndWait(const std::function<void(VkCommandBuffer)>& record);
    void submitAndWait(VkCommandBuffer cmd, VkCommandBuffer after = VK_NULL_HANDLE);
    // A buffer upload ordered before the next submission, without one of its own
    // (core/gpu/upload_queue.h); false when it is too large to hold (upload it directly).
    bool queueUpload(const Buffer& dst, const void* data, VkDeviceSize size);
    // Submits the queued uploads now and waits (a submission not made through this context,
    // or a buffer they write about to be destroyed).
    void flushUploads();
    bool uploadsWrite(VkBuffer buffer) const;
    VkCommandBuffer allocateCommandBuffer();
    void freeCommandBuffer(VkCommandBuffer cmd);
    // Holds this context's queue for a submission or present of one's own (vkQueueSubmit and
    // vkQueuePresentKHR need the queue externally synchronized: a shared queue's other context
    // may submit from its thread).
    std::unique_lock<std::mutex> lockQueue() const { return std::unique_lock<std::mutex>(*queueMutex_); }
    // Waits for this context's queue (a shared device: not the device, whose other queue
    // another thread submits to; vkDeviceWaitIdle would race that thread's submissions).
    void waitIdle();
    uint32_t queueCount = 1;      // queues the device was created with in queueFamily
    bool sharesDevice() const { return !ownsDevice_; }

    // Validation messages (warnings and errors) seen since creation; tests assert none.
    std::vector<std::string> validationMessages() const;

  private:
    GpuContext() = default;
    void createPoolAndFence();
    friend VkBool32 debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                  VkDebugUtilsMessageTypeFlagsEXT,
                                  const VkDebugUtilsMessengerCallbackDataEXT*, void*);
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    std::unique_ptr<UploadQueue> uploads_;
    bool ownsDevice_ = true;
    std::shared_ptr<std::mutex> queueMutex_ = std::make_shared<std::mutex>();
    mutable std::mutex messagesMutex_;
    std::vector<std::string> messages_;
};

} // namespace tp
