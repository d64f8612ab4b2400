#include "gpu/device.hpp"

#include <cstring>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/util/error.hpp"
#include "gpu/vk_check.hpp"

namespace ts::gpu {
namespace {

// The portability-subset extension is not in every header; its name is fixed by the spec.
constexpr const char* kPortabilitySubset = "VK_KHR_portability_subset";

bool has_device_extension(VkPhysicalDevice device, const char* name) {
    std::uint32_t count = 0;
    check(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr), "vkEnumerateDeviceExtensionProperties");
    std::vector<VkExtensionProperties> extensions(count);
    check(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data()),
          "vkEnumerateDeviceExtensionProperties");
    for (const auto& extension : extensions) {
        if (std::strcmp(extension.extensionName, name) == 0) return true;
    }
    return false;
}

}  // namespace

Device::Device(const PhysicalDeviceInfo& physical, const std::vector<std::string>& extra)
    : physical_(physical.handle), limits_(physical.limits) {
    if (!physical.usable()) throw std::logic_error("gpu::Device: " + physical.name + " " + physical.unusable_reason);
    queue_family_ = *physical.compute_queue_family;
    vkGetPhysicalDeviceMemoryProperties(physical_, &memory_properties_);

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue_info{};
    queue_info.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queue_info.queueFamilyIndex = queue_family_;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;

    // The spec requires enabling the portability subset wherever a device offers it (MoltenVK).
    std::vector<const char*> extensions;
    if (has_device_extension(physical_, kPortabilitySubset)) extensions.push_back(kPortabilitySubset);
    for (const std::string& name : extra) {
        if (!has_device_extension(physical_, name.c_str()))
            throw InputError("vulkan: " + physical.name + " lacks the device extension " + name);
        extensions.push_back(name.c_str());
    }

    VkDeviceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue_info;
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    check(vkCreateDevice(physical_, &info, nullptr, &device_), "vkCreateDevice");
    vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
}

Device::~Device() { destroy(); }

Device::Device(Device&& other) noexcept
    : device_(std::exchange(other.device_, VK_NULL_HANDLE)),
      physical_(other.physical_),
      queue_(other.queue_),
      queue_family_(other.queue_family_),
      memory_properties_(other.memory_properties_),
      limits_(other.limits_) {}

Device& Device::operator=(Device&& other) noexcept {
    if (this != &other) {
        destroy();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        physical_ = other.physical_;
        queue_ = other.queue_;
        queue_family_ = other.queue_family_;
        memory_properties_ = other.memory_properties_;
        limits_ = other.limits_;
    }
    return *this;
}

void Device::wait_idle() const { check(vkDeviceWaitIdle(device_), "vkDeviceWaitIdle"); }

void Device::destroy() {
    if (device_ == VK_NULL_HANDLE) return;
    vkDeviceWaitIdle(device_);  // nothing may still run on objects about to go
    vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
}

}  // namespace ts::gpu
