#include "gpu/physical_device.hpp"

#include "gpu/instance.hpp"
#include "gpu/vk_check.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::gpu {
namespace {

// Lower is preferred.
int type_rank(VkPhysicalDeviceType type) {
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

// A family that also does graphics is the main queue on every driver; a compute-only family
// is taken when it is all there is.
std::optional<std::uint32_t> find_compute_queue_family(VkPhysicalDevice device) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    std::optional<std::uint32_t> compute_only;
    for (std::uint32_t i = 0; i < count; ++i) {
        const VkQueueFlags flags = families[i].queueFlags;
        if (families[i].queueCount == 0 || !(flags & VK_QUEUE_COMPUTE_BIT)) continue;
        if (flags & VK_QUEUE_GRAPHICS_BIT) return i;
        if (!compute_only) compute_only = i;
    }
    return compute_only;
}

}  // namespace

std::vector<PhysicalDeviceInfo> enumerate_physical_devices(VkInstance instance) {
    std::uint32_t count = 0;
    check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> handles(count);
    check(vkEnumeratePhysicalDevices(instance, &count, handles.data()), "vkEnumeratePhysicalDevices");
    handles.resize(count);

    std::vector<PhysicalDeviceInfo> devices;
    for (std::uint32_t i = 0; i < count; ++i) {
        VkPhysicalDeviceProperties properties{};
        vkGetPhysicalDeviceProperties(handles[i], &properties);
        PhysicalDeviceInfo info;
        info.index = i;
        info.handle = handles[i];
        info.name = properties.deviceName;
        info.type = properties.deviceType;
        info.api_version = properties.apiVersion;
        info.limits = properties.limits;
        info.compute_queue_family = find_compute_queue_family(handles[i]);
        if (info.compute_queue_family) {
            std::uint32_t family_count = 0;
            vkGetPhysicalDeviceQueueFamilyProperties(handles[i], &family_count, nullptr);
            std::vector<VkQueueFamilyProperties> families(family_count);
            vkGetPhysicalDeviceQueueFamilyProperties(handles[i], &family_count, families.data());
            info.timestamp_valid_bits = families[*info.compute_queue_family].timestampValidBits;
        }
        if (properties.apiVersion < VK_API_VERSION_1_1) {
            info.unusable_reason = "supports only Vulkan " + api_version_string(properties.apiVersion) + ", needs 1.1";
        } else if (!info.compute_queue_family) {
            info.unusable_reason = "has no compute queue";
        }
        devices.push_back(std::move(info));
    }
    return devices;
}

const char* device_type_name(VkPhysicalDeviceType type) {
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

std::string api_version_string(std::uint32_t version) {
    return std::to_string(VK_API_VERSION_MAJOR(version)) + "." + std::to_string(VK_API_VERSION_MINOR(version)) + "." +
           std::to_string(VK_API_VERSION_PATCH(version));
}

std::optional<std::uint32_t> default_device_index(std::span<const PhysicalDeviceInfo> devices) {
    std::optional<std::uint32_t> best;
    for (const auto& device : devices) {
        if (!device.usable()) continue;
        if (!best || type_rank(device.type) < type_rank(devices[*best].type)) best = device.index;
    }
    return best;
}

const PhysicalDeviceInfo& choose_device(std::span<const PhysicalDeviceInfo> devices,
                                        std::optional<std::uint32_t> requested) {
    if (devices.empty()) throw no_vulkan_device_error("no Vulkan device found");
    if (requested) {
        if (*requested >= devices.size()) {
            throw QuantityError(Quantity::device, std::to_string(*requested), "no such Vulkan device, indices go from 0 to " +
                             std::to_string(devices.size() - 1) + " (see terrashade devices)");
        }
        const PhysicalDeviceInfo& device = devices[*requested];
        if (!device.usable()) {
            throw QuantityError(Quantity::device, std::to_string(*requested), device.name + " " + device.unusable_reason);
        }
        return device;
    }
    const auto best = default_device_index(devices);
    if (!best) throw no_vulkan_device_error("no Vulkan device with Vulkan 1.1 and a compute queue");
    return devices[*best];
}

AutoPath choose_auto_path(std::span<const PhysicalDeviceInfo> devices) {
    const auto best = default_device_index(devices);
    if (!best) {
        return {std::nullopt, devices.empty() ? "no Vulkan device found: the CPU path"
                                              : "no usable Vulkan device (Vulkan 1.1 with a compute queue): the CPU path"};
    }
    const PhysicalDeviceInfo& d = devices[*best];
    const bool gpu = d.type == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU || d.type == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU ||
                     d.type == VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU;
    if (gpu) return {*best, std::string(device_type_name(d.type)) + " GPU " + d.name + " (device " +
                                std::to_string(d.index) + "): the Vulkan path"};
    return {std::nullopt, "the best Vulkan device, " + d.name + ", is a " + device_type_name(d.type) +
                              " implementation that runs on the same cores as the CPU path, which is faster there: "
                              "the CPU path (asking for the Vulkan device forces it)"};
}

}  // namespace ts::gpu
