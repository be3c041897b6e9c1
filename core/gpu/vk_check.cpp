#include "core/gpu/vk_check.h"

#include <cstring>

namespace tp {

const char* vkResultName(VkResult result) {
    switch (result) {
#define TP_CASE(x)                                                                                 \
    case x:                                                                                        \
        return #x;
        TP_CASE(VK_SUCCESS)
        TP_CASE(VK_NOT_READY)
        TP_CASE(VK_TIMEOUT)
        TP_CASE(VK_INCOMPLETE)
        TP_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        TP_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        TP_CASE(VK_ERROR_INITIALIZATION_FAILED)
        TP_CASE(VK_ERROR_DEVICE_LOST)
        TP_CASE(VK_ERROR_MEMORY_MAP_FAILED)
        TP_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        TP_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
        TP_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        TP_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
        TP_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        TP_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        TP_CASE(VK_ERROR_FRAGMENTED_POOL)
        TP_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
        TP_CASE(VK_ERROR_UNKNOWN)
#undef TP_CASE
    default:
        return "VK_ERROR_(unnamed)";
    }
}

void throwVkError(VkResult result, const char* call, const char* file, int line) {
    const char* base = std::strrchr(file, '/');
    throw GpuError(std::string(base ? base + 1 : file) + ":" + std::to_string(line) + ": " + call +
                   " failed with " + vkResultName(result));
}

} // namespace tp
