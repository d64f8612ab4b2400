#include "gpu/buffer.hpp"

#include <algorithm>
#include <utility>

#include "gpu/vk_check.hpp"

namespace ts::gpu {

std::uint32_t find_memory_type(const VkPhysicalDeviceMemoryProperties& properties, std::uint32_t type_bits,
                               VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) {
    const VkMemoryPropertyFlags wanted[] = {required | preferred, required};
    for (const VkMemoryPropertyFlags flags : wanted) {
        for (std::uint32_t i = 0; i < properties.memoryTypeCount; ++i) {
            const bool allowed = (type_bits & (1u << i)) != 0;
            if (allowed && (properties.memoryTypes[i].propertyFlags & flags) == flags) return i;
        }
    }
    throw VulkanError("find_memory_type (no memory type fits)", VK_ERROR_FEATURE_NOT_PRESENT);
}

Buffer::Buffer(const Device& device, VkDeviceSize bytes, MemoryKind kind, VkBufferUsageFlags extra_usage)
    : size_(bytes), kind_(kind) {
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = std::max<VkDeviceSize>(bytes, 4);
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                 VK_BUFFER_USAGE_TRANSFER_DST_BIT | extra_usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    check(vkCreateBuffer(device.get(), &info, nullptr, &buffer), "vkCreateBuffer");
    buffer_ = {device.get(), buffer, vkDestroyBuffer};

    VkMemoryRequirements requirements{};
    vkGetBufferMemoryRequirements(device.get(), buffer, &requirements);
    // Cached host memory makes reading results back fast; uploads do not suffer from it much.
    const std::uint32_t type =
        kind == MemoryKind::device_local
            ? find_memory_type(device.memory_properties(), requirements.memoryTypeBits, 0,
                               VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT)
            : find_memory_type(device.memory_properties(), requirements.memoryTypeBits,
                               VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                               VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
    VkMemoryAllocateInfo allocate{};
    allocate.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    allocate.allocationSize = requirements.size;
    allocate.memoryTypeIndex = type;
    memory_properties_ = device.memory_properties().memoryTypes[type].propertyFlags;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    check(vkAllocateMemory(device.get(), &allocate, nullptr, &memory), "vkAllocateMemory");
    memory_ = {device.get(), memory, vkFreeMemory};
    check(vkBindBufferMemory(device.get(), buffer, memory, 0), "vkBindBufferMemory");

    if (kind == MemoryKind::host_visible) {
        void* pointer = nullptr;
        // Stays mapped for the buffer's life; vkFreeMemory unmaps it.
        check(vkMapMemory(device.get(), memory, 0, VK_WHOLE_SIZE, 0, &pointer), "vkMapMemory");
        mapped_ = static_cast<std::byte*>(pointer);
    }
}

Buffer::Buffer(Buffer&& other) noexcept
    : memory_(std::move(other.memory_)),
      buffer_(std::move(other.buffer_)),
      size_(std::exchange(other.size_, 0)),
      kind_(other.kind_),
      mapped_(std::exchange(other.mapped_, nullptr)),
      memory_properties_(std::exchange(other.memory_properties_, 0)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this != &other) {
        buffer_ = std::move(other.buffer_);  // the old buffer goes before the old memory
        memory_ = std::move(other.memory_);
        size_ = std::exchange(other.size_, 0);
        kind_ = other.kind_;
        mapped_ = std::exchange(other.mapped_, nullptr);
        memory_properties_ = std::exchange(other.memory_properties_, 0);
    }
    return *this;
}

}  // namespace ts::gpu
