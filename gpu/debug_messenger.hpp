#pragma once
// VK_EXT_debug_utils messenger that records every validation warning and error in a
// ValidationLog (and, through it, echoes them to stderr).
#include "gpu/vulkan_api.hpp"

#include "gpu/validation_log.hpp"

namespace ts::gpu {

// The create-info both the messenger and vkCreateInstance's pNext chain use.
VkDebugUtilsMessengerCreateInfoEXT debug_messenger_create_info(ValidationLog& log);

class DebugMessenger {
public:
    DebugMessenger() = default;
    // log must outlive the messenger.
    DebugMessenger(VkInstance instance, ValidationLog& log);
    ~DebugMessenger();
    DebugMessenger(const DebugMessenger&) = delete;
    DebugMessenger& operator=(const DebugMessenger&) = delete;
    DebugMessenger(DebugMessenger&& other) noexcept;
    DebugMessenger& operator=(DebugMessenger&& other) noexcept;

private:
    void reset();

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
};

}  // namespace ts::gpu
