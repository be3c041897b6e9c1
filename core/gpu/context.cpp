#include "core/gpu/context.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "core/gpu/upload_queue.h" // ~GpuContext destroys the queue
#include "core/gpu/vk_check.h"

namespace tp {
namespace {

const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string deviceTypeName(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return "virtual";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return "cpu";
    default:
        return "other";
    }
}

int typeRank(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return 3;
    default:
        return 4;
    }
}

bool layerPresent(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    for (const VkLayerProperties& l : layers)
        if (std::strcmp(l.layerName, name) == 0) return true;
    return false;
}

Result<VkInstance> createInstance(bool validate, const std::vector<std::string>& extra) {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "triptych";
    app.apiVersion = VK_API_VERSION_1_3;
    std::vector<const char*> layers, extensions;
    VkValidationFeatureEnableEXT enables[] = {
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enables;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    if (validate) {
        if (!layerPresent(kValidationLayer))
            return Error{"--validate: the Khronos validation layer is not installed "
                         "(apt-get install vulkan-validationlayers)"};
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        info.pNext = &features;
    }
    for (const std::string& e : extra)
        extensions.push_back(e.c_str());
    info.enabledLayerCount = uint32_t(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkInstance instance = VK_NULL_HANDLE;
    VkResult r = vkCreateInstance(&info, nullptr, &instance);
    // The result named: on the H200 the NVIDIA driver refuses a process's 31st instance (one
    // made and destroyed per test, in one test process) with one of these two, and a bare "no
    // driver" sent that search the wrong way (docs/build.md, "GPU tests").
    if (r == VK_ERROR_INCOMPATIBLE_DRIVER || r == VK_ERROR_INITIALIZATION_FAILED)
        return Error{std::string("no Vulkan 1.3 driver found (vkCreateInstance: ") +
                     vkResultName(r) + "; install mesa-vulkan-drivers for lavapipe)"};
    if (r != VK_SUCCESS)
        return Error{std::string("vkCreateInstance failed with ") + vkResultName(r)};
    return instance;
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance, &count, devices.data());
    // Only Vulkan 1.3 devices can run triptych.
    std::erase_if(devices, [](VkPhysicalDevice d) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(d, &p);
        return p.apiVersion < VK_API_VERSION_1_3;
    });
    return devices;
}

DeviceInfo describe(VkPhysicalDevice device, uint32_t index) {
    VkPhysicalDeviceIDProperties id{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ID_PROPERTIES};
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES, &id};
    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
    vkGetPhysicalDeviceProperties2(device, &props);
    DeviceInfo info;
    info.index = index;
    info.name = props.properties.deviceName;
    info.type = deviceTypeName(props.properties.deviceType);
    info.driver = std::string(driver.driverName) + " " + driver.driverInfo;
    info.apiVersion = props.properties.apiVersion;
    info.vendorId = props.properties.vendorID;
    std::copy(std::begin(id.deviceUUID), std::end(id.deviceUUID), info.uuid.begin());
    return info;
}

Result<uint32_t> chooseDevice(const std::vector<VkPhysicalDevice>& devices,
                              const std::string& want) {
    if (devices.empty())
        return Error{"no Vulkan 1.3 device found (install mesa-vulkan-drivers for lavapipe)"};
    if (want.empty()) {
        uint32_t best = 0;
        for (uint32_t i = 1; i < devices.size(); ++i) {
            VkPhysicalDeviceProperties a, b;
            vkGetPhysicalDeviceProperties(devices[i], &a);
            vkGetPhysicalDeviceProperties(devices[best], &b);
            if (typeRank(a.deviceType) < typeRank(b.deviceType)) best = i;
        }
        return best;
    }
    bool numeric =
        std::all_of(want.begin(), want.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (numeric) {
        unsigned long i = std::strtoul(want.c_str(), nullptr, 10);
        if (i < devices.size()) return uint32_t(i);
        return Error{"--device " + want + ": no such device (there are " +
                     std::to_string(devices.size()) + "; see 'triptych info')"};
    }
    for (uint32_t i = 0; i < devices.size(); ++i) {
        std::string name = describe(devices[i], i).name;
        std::string lower = name, key = want;
        std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
        std::transform(key.begin(), key.end(), key.begin(), ::tolower);
        if (lower.find(key) != std::string::npos) return i;
    }
    return Error{"--device " + want + ": no device name contains it (see 'triptych info')"};
}

DeviceCaps readCaps(VkPhysicalDevice device, const VkPhysicalDeviceProperties& p) {
    VkPhysicalDeviceFeatures f;
    vkGetPhysicalDeviceFeatures(device, &f);
    VkPhysicalDeviceVulkan13Properties p13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_PROPERTIES};
    VkPhysicalDeviceSubgroupProperties sub{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES,
                                           &p13};
    VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &sub};
    vkGetPhysicalDeviceProperties2(device, &p2);
    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                         &f13};
    VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &f12};
    vkGetPhysicalDeviceFeatures2(device, &f2);
    DeviceCaps c;
    c.float64 = f.shaderFloat64;
    c.sampleRateShading = f.sampleRateShading;
    c.pipelineStatisticsQuery = f.pipelineStatisticsQuery;
    c.storageImageMultisample = f.shaderStorageImageMultisample;
    c.fragmentStoresAndAtomics = f.fragmentStoresAndAtomics;
    c.colorSampleCounts =
        p.limits.framebufferColorSampleCounts & p.limits.framebufferDepthSampleCounts;
    c.timestampPeriodNs = p.limits.timestampPeriod;
    c.maxImageDimension2D = p.limits.maxImageDimension2D;
    c.maxStorageBufferRange = p.limits.maxStorageBufferRange;
    c.maxComputeSharedMemorySize = p.limits.maxComputeSharedMemorySize;
    c.subgroupSize = sub.subgroupSize;
    c.subgroupStages = sub.supportedStages;
    c.subgroupOps = sub.supportedOperations;
    c.computeFullSubgroups = f13.subgroupSizeControl && f13.computeFullSubgroups &&
                             (p13.requiredSubgroupSizeStages & VK_SHADER_STAGE_COMPUTE_BIT) &&
                             p13.minSubgroupSize <= sub.subgroupSize &&
                             sub.subgroupSize <= p13.maxSubgroupSize;
    c.standardSampleLocations = p.limits.standardSampleLocations;
    c.geometryShader = f.geometryShader;
    c.drawIndirectCount = f12.drawIndirectCount && f.multiDrawIndirect;
    c.drawIndirectFirstInstance = f.drawIndirectFirstInstance;
    c.int64Atomics = f.shaderInt64 && f12.shaderBufferInt64Atomics;
    c.dualSrcBlend = f.dualSrcBlend;
    return c;
}

// The first queue family with graphics, compute and timestamps (-1: none); `timestampBits`
// receives its timestampValidBits.
int findQueueFamily(VkPhysicalDevice physical, uint32_t& timestampBits) {
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &familyCount, families.data());
    for (uint32_t i = 0; i < familyCount; ++i) {
        VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
        if ((families[i].queueFlags & need) == need && families[i].timestampValidBits > 0) {
            timestampBits = families[i].timestampValidBits;
            return int(i);
        }
    }
    return -1;
}

uint32_t familyQueues(VkPhysicalDevice physical, uint32_t family) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
    return family < count ? families[family].queueCount : 1;
}

// `queues` (1 or 2) queues of `family`; the features the renderers use where `caps` has them.
VkResult createLogicalDevice(VkPhysicalDevice physical, uint32_t family, const DeviceCaps& caps,
                             bool swapchain, uint32_t queues, VkDevice& device) {
    const float priorities[2] = {1.0f, 1.0f};
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = family;
    queueInfo.queueCount = std::min(queues, 2u);
    queueInfo.pQueuePriorities = priorities;

    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    f13.dynamicRendering = VK_TRUE;
    f13.synchronization2 = VK_TRUE;
    // Required by Vulkan 1.3; glslang's vulkan1.3 target writes compute workgroup sizes as
    // LocalSizeId, which the validation layers accept only with maintenance4 enabled.
    f13.maintenance4 = VK_TRUE;
    f13.subgroupSizeControl = caps.computeFullSubgroups;
    f13.computeFullSubgroups = caps.computeFullSubgroups;
    VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                         &f13};
    f12.hostQueryReset = VK_TRUE;
    f12.scalarBlockLayout = VK_FALSE;
    f12.drawIndirectCount = caps.drawIndirectCount;
    f12.shaderBufferInt64Atomics = caps.int64Atomics;
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &f12};
    features.features.shaderFloat64 = caps.float64;
    features.features.sampleRateShading = caps.sampleRateShading;
    features.features.pipelineStatisticsQuery = caps.pipelineStatisticsQuery;
    features.features.shaderStorageImageMultisample = caps.storageImageMultisample;
    features.features.fragmentStoresAndAtomics = caps.fragmentStoresAndAtomics;
    features.features.independentBlend = VK_TRUE;
    features.features.geometryShader = caps.geometryShader;
    features.features.multiDrawIndirect = caps.drawIndirectCount;
    features.features.drawIndirectFirstInstance = caps.drawIndirectFirstInstance;
    features.features.shaderInt64 = caps.int64Atomics;
    features.features.dualSrcBlend = caps.dualSrcBlend;

    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features};
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    const char* swapchainExtension = VK_KHR_SWAPCHAIN_EXTENSION_NAME;
    if (swapchain) {
        deviceInfo.enabledExtensionCount = 1;
        deviceInfo.ppEnabledExtensionNames = &swapchainExtension;
    }
    return vkCreateDevice(physical, &deviceInfo, nullptr, &device);
}

} // namespace

VkBool32 debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                       VkDebugUtilsMessageTypeFlagsEXT,
                       const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* ctx = static_cast<GpuContext*>(user);
    if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
        std::lock_guard<std::mutex> lock(ctx->messagesMutex_);
        ctx->messages_.push_back(data->pMessage ? data->pMessage : "(no message)");
    }
    return VK_FALSE;
}

namespace {

// Warnings and errors, to debugCallback with `userData` (the context).
VkDebugUtilsMessengerEXT createMessenger(VkInstance instance, void* userData) {
    VkDebugUtilsMessengerEXT messenger;
    VkDebugUtilsMessengerCreateInfoEXT info{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = debugCallback;
    info.pUserData = userData;
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    VK_CHECK(create(instance, &info, nullptr, &messenger));
    return messenger;
}

} // namespace

Result<std::vector<DeviceInfo>> GpuContext::listDevices() {
    Result<VkInstance> instance = createInstance(false, {});
    if (!instance) return Error{instance.error()};
    std::vector<DeviceInfo> out;
    std::vector<VkPhysicalDevice> devices = physicalDevices(*instance);
    for (uint32_t i = 0; i < devices.size(); ++i)
        out.push_back(describe(devices[i], i));
    vkDestroyInstance(*instance, nullptr);
    return out;
}

Result<std::unique_ptr<GpuContext>> GpuContext::create(const ContextOptions& options) {
    std::unique_ptr<GpuContext> ctx(new GpuContext());
    Result<VkInstance> instance = createInstance(options.validate, options.instanceExtensions);
    if (!instance) return Error{instance.error()};
    ctx->instance = *instance;
    if (options.validate) ctx->messenger_ = createMessenger(ctx->instance, ctx.get());
    std::vector<VkPhysicalDevice> devices = physicalDevices(ctx->instance);
    Result<uint32_t> chosen = chooseDevice(devices, options.device);
    if (!chosen) return Error{chosen.error()};
    ctx->physical = devices[*chosen];
    ctx->info = describe(ctx->physical, *chosen);
    vkGetPhysicalDeviceProperties(ctx->physical, &ctx->properties);
    vkGetPhysicalDeviceMemoryProperties(ctx->physical, &ctx->memoryProperties);
    ctx->caps = readCaps(ctx->physical, ctx->properties);

    const int family = findQueueFamily(ctx->physical, ctx->caps.timestampValidBits);
    if (family < 0)
        return Error{"device '" + ctx->info.name +
                     "' has no graphics+compute queue with timestamps"};
    ctx->queueFamily = uint32_t(family);

    ctx->queueCount =
        std::clamp(options.queues, 1u, std::min(2u, familyQueues(ctx->physical, ctx->queueFamily)));
    VkResult r = createLogicalDevice(ctx->physical, ctx->queueFamily, ctx->caps, options.swapchain,
                                     ctx->queueCount, ctx->device);
    if (r != VK_SUCCESS)
        return Error{"cannot create a Vulkan device on '" + ctx->info.name +
                     "': " + vkResultName(r)};
    vkGetDeviceQueue(ctx->device, ctx->queueFamily, 0, &ctx->queue);
    ctx->createPoolAndFence();
    return ctx;
}

std::unique_ptr<GpuContext> GpuContext::share(GpuContext& owner, uint32_t queueIndex) {
    std::unique_ptr<GpuContext> ctx(new GpuContext());
    ctx->ownsDevice_ = false;
    ctx->instance = owner.instance;
    ctx->physical = owner.physical;
    ctx->device = owner.device;
    ctx->queueFamily = owner.queueFamily;
    ctx->queueCount = owner.queueCount;
    ctx->properties = owner.properties;
    ctx->memoryProperties = owner.memoryProperties;
    ctx->caps = owner.caps;
    ctx->info = owner.info;
    if (queueIndex < owner.queueCount) {
        vkGetDeviceQueue(ctx->device, ctx->queueFamily, queueIndex, &ctx->queue);
        if (ctx->queue == owner.queue) ctx->queueMutex_ = owner.queueMutex_;
    } else {
        ctx->queue = owner.queue;
        ctx->queueMutex_ = owner.queueMutex_;
    }
    ctx->createPoolAndFence();
    return ctx;
}

void GpuContext::createPoolAndFence() {
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = queueFamily;
    VK_CHECK(vkCreateCommandPool(device, &poolInfo, nullptr, &commandPool));
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(device, &fenceInfo, nullptr, &fence_));
    uploads_ = std::make_unique<UploadQueue>(*this);
}

GpuContext::~GpuContext() {
    uploads_.reset(); // what is queued is for a submission that will not come
    if (device && !ownsDevice_) {
        waitIdle();
        vkDestroyFence(device, fence_, nullptr);
        vkDestroyCommandPool(device, commandPool, nullptr);
        return; // the owner's device, instance and messenger
    }
    if (device) {
        vkDeviceWaitIdle(device);
        vkDestroyFence(device, fence_, nullptr);
        vkDestroyCommandPool(device, commandPool, nullptr);
        vkDestroyDevice(device, nullptr);
    }
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance, messenger_, nullptr);
    }
    if (instance) vkDestroyInstance(instance, nullptr);
}

bool GpuContext::reducesFragmentsBySubgroup() const {
    const VkSubgroupFeatureFlags need = VK_SUBGROUP_FEATURE_BASIC_BIT |
                                        VK_SUBGROUP_FEATURE_BALLOT_BIT |
                                        VK_SUBGROUP_FEATURE_ARITHMETIC_BIT;
    return !isCpuDevice() && (caps.subgroupStages & VK_SHADER_STAGE_FRAGMENT_BIT) &&
           (caps.subgroupOps & need) == need;
}

std::vector<std::string> GpuContext::validationMessages() const {
    std::lock_guard<std::mutex> lock(messagesMutex_);
    return messages_;
}

} // namespace tp
