#pragma once
// VK_CHECK stays on in release builds: a failing call throws GpuError naming the file,
// line, call and VkResult; the CLI catches it at its boundary and exits non-zero.
#include <stdexcept>
#include <string>

#include <vulkan/vulkan.h>

namespace tp {

class GpuError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

const char* vkResultName(VkResult result);
[[noreturn]] void throwVkError(VkResult result, const char* call, const char* file, int line);

} // namespace tp

#define VK_CHECK(call)                                                                             \
    do {                                                                                           \
        VkResult vk_check_result_ = (call);                                                        \
        if (vk_check_result_ != VK_SUCCESS)                                                        \
            ::tp::throwVkError(vk_check_result_, #call, __FILE__, __LINE__);                       \
    } while (0)
