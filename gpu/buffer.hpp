#pragma once
// A VkBuffer with its own VkDeviceMemory (one allocation per buffer: terrashade makes few,
// large buffers, far below maxMemoryAllocationCount). Every buffer can be a storage buffer and
// a transfer source and destination, so any buffer can be bound to any kernel or copied.
#include <cstddef>
#include <cstdint>

#include "gpu/vulkan_api.hpp"

#include "gpu/device.hpp"
#include "gpu/handle.hpp"

namespace ts::gpu {

enum class MemoryKind {
    device_local,  // where kernels read and write fast; filled and read through staging copies
    host_visible,  // mapped, coherent: the staging side of uploads and downloads
};

class Buffer {
public:
    Buffer() = default;
    // bytes may be 0 (an empty input); Vulkan needs a non-empty buffer, so 4 bytes are made.
    Buffer(const Device& device, VkDeviceSize bytes, MemoryKind kind, VkBufferUsageFlags extra_usage = 0);
    Buffer(Buffer&& other) noexcept;
    Buffer& operator=(Buffer&& other) noexcept;

    VkBuffer get() const { return buffer_.get(); }
    VkDeviceSize size() const { return size_; }  // what was asked for
    MemoryKind kind() const { return kind_; }
    // The mapped bytes of a host_visible buffer (coherent: no flush needed); nullptr otherwise.
    std::byte* mapped() const { return mapped_; }
    // The property flags of the memory type the buffer lives in (e.g. whether host_visible
    // memory is also device-local and cached, so kernels may write results straight into it).
    VkMemoryPropertyFlags memory_properties() const { return memory_properties_; }

private:
    // Declared before buffer_ so the buffer goes first and the memory after it.
    DeviceHandle<VkDeviceMemory> memory_;
    DeviceHandle<VkBuffer> buffer_;
    VkDeviceSize size_ = 0;
    MemoryKind kind_ = MemoryKind::device_local;
    std::byte* mapped_ = nullptr;
    VkMemoryPropertyFlags memory_properties_ = 0;
};

// The index of a memory type allowed by type_bits with all `required` flags, preferring one
// that also has `preferred`; throws VulkanError if none fits.
std::uint32_t find_memory_type(const VkPhysicalDeviceMemoryProperties& properties, std::uint32_t type_bits,
                               VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred);

}  // namespace ts::gpu
