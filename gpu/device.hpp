#pragma once
// The logical device with one compute queue. Everything else (buffers, pipelines, command
// pools) is created from it and must be destroyed before it.
#include <cstdint>
#include <string>
#include <vector>

#include "gpu/vulkan_api.hpp"

#include "gpu/physical_device.hpp"

namespace ts::gpu {

class Device {
public:
    // `extensions`: device extensions to enable besides the portability subset (a window's
    // VK_KHR_swapchain); ts::InputError if the device lacks one.
    explicit Device(const PhysicalDeviceInfo& physical, const std::vector<std::string>& extensions = {});
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;
    Device(Device&& other) noexcept;
    Device& operator=(Device&& other) noexcept;

    VkDevice get() const { return device_; }
    VkPhysicalDevice physical() const { return physical_; }
    VkQueue queue() const { return queue_; }
    std::uint32_t queue_family() const { return queue_family_; }
    const VkPhysicalDeviceMemoryProperties& memory_properties() const { return memory_properties_; }
    const VkPhysicalDeviceLimits& limits() const { return limits_; }

    // Blocks until the queue has finished everything submitted (used before teardown).
    void wait_idle() const;

private:
    void destroy();

    VkDevice device_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    std::uint32_t queue_family_ = 0;
    VkPhysicalDeviceMemoryProperties memory_properties_{};
    VkPhysicalDeviceLimits limits_{};
};

}  // namespace ts::gpu
