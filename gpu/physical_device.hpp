#pragma once
// What the instance can see, and which device terrashade uses: a discrete GPU before an
// integrated one, before a virtual one, before a CPU implementation (lavapipe), unless the
// user names one with --device N. A device is usable if it speaks Vulkan 1.1 and has a
// queue family that can run compute.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gpu/vulkan_api.hpp"

namespace ts::gpu {

struct PhysicalDeviceInfo {
    std::uint32_t index = 0;  // position in vkEnumeratePhysicalDevices, what --device takes
    VkPhysicalDevice handle = VK_NULL_HANDLE;
    std::string name;
    VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
    std::uint32_t api_version = 0;
    VkPhysicalDeviceLimits limits{};
    std::optional<std::uint32_t> compute_queue_family;
    std::uint32_t timestamp_valid_bits = 0;  // of that family; 0: no GPU timestamps
    std::string unusable_reason;  // empty when the device can run terrashade

    bool usable() const { return unusable_reason.empty(); }
};

std::vector<PhysicalDeviceInfo> enumerate_physical_devices(VkInstance instance);

// "discrete", "integrated", "virtual", "cpu" or "other".
const char* device_type_name(VkPhysicalDeviceType type);

// "1.3.230".
std::string api_version_string(std::uint32_t version);

// The usable device terrashade picks when not told: best type first, then lowest index.
std::optional<std::uint32_t> default_device_index(std::span<const PhysicalDeviceInfo> devices);

// The device to use: `requested` if given (ts::InputError if out of range or unusable),
// else the default (ts::InputError naming the package to install if there is none).
const PhysicalDeviceInfo& choose_device(std::span<const PhysicalDeviceInfo> devices,
                                        std::optional<std::uint32_t> requested);

// What `--device auto` runs on: the device default_device_index picks when it is a GPU
// (discrete, integrated or virtual), else the CPU path (no device): a CPU implementation of
// Vulkan (lavapipe, llvmpipe, SwiftShader) runs the same cores as the CPU path, and slower.
// `reason` says why in one sentence, for `terrashade devices` and --verbose.
struct AutoPath {
    std::optional<std::uint32_t> device;  // empty: the CPU path
    std::string reason;
};
AutoPath choose_auto_path(std::span<const PhysicalDeviceInfo> devices);

}  // namespace ts::gpu
