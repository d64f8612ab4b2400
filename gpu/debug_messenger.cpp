#include "gpu/debug_messenger.hpp"

#include <string>
#include <utility>

#include "gpu/vk_check.hpp"

namespace ts::gpu {
namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL record_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT types,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    std::string text = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
    if (types & VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT) text += " (validation)";
    if (types & VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT) text += " (performance)";
    text += ": ";
    text += data->pMessage != nullptr ? data->pMessage : "(no message)";
    static_cast<ValidationLog*>(user)->add(std::move(text));
    return VK_FALSE;  // the spec: applications must return false (do not abort the call)
}

}  // namespace

VkDebugUtilsMessengerCreateInfoEXT debug_messenger_create_info(ValidationLog& log) {
    VkDebugUtilsMessengerCreateInfoEXT info{};
    info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    info.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = record_message;
    info.pUserData = &log;
    return info;
}

DebugMessenger::DebugMessenger(VkInstance instance, ValidationLog& log) : instance_(instance) {
    // An extension function: reached through the instance, not linked.
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    if (create == nullptr) throw VulkanError("vkCreateDebugUtilsMessengerEXT", VK_ERROR_EXTENSION_NOT_PRESENT);
    const VkDebugUtilsMessengerCreateInfoEXT info = debug_messenger_create_info(log);
    check(create(instance, &info, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
}

DebugMessenger::~DebugMessenger() { reset(); }

DebugMessenger::DebugMessenger(DebugMessenger&& other) noexcept
    : instance_(other.instance_), messenger_(std::exchange(other.messenger_, VK_NULL_HANDLE)) {}

DebugMessenger& DebugMessenger::operator=(DebugMessenger&& other) noexcept {
    if (this != &other) {
        reset();
        instance_ = other.instance_;
        messenger_ = std::exchange(other.messenger_, VK_NULL_HANDLE);
    }
    return *this;
}

void DebugMessenger::reset() {
    if (messenger_ == VK_NULL_HANDLE) return;
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy != nullptr) destroy(instance_, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
}

}  // namespace ts::gpu
