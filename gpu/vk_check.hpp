#pragma once
// Turning VkResult codes into exceptions, so every wrapper can say `check(vkFoo(...), "vkFoo")`.
#include <stdexcept>
#include <string>

#include "gpu/vulkan_api.hpp"

namespace ts::gpu {

// A Vulkan call failed. what() names the call and the result ("vkCreateBuffer:
// VK_ERROR_OUT_OF_DEVICE_MEMORY"); result() gives the code for callers that can recover.
class VulkanError : public std::runtime_error {
public:
    VulkanError(const char* call, VkResult result);
    VkResult result() const { return result_; }

private:
    VkResult result_;
};

// "VK_ERROR_DEVICE_LOST" for VK_ERROR_DEVICE_LOST, and so on.
const char* result_name(VkResult result);

// Throws VulkanError unless result is VK_SUCCESS (or another non-negative success code).
inline void check(VkResult result, const char* call) {
    if (result < 0) throw VulkanError(call, result);
}

}  // namespace ts::gpu
