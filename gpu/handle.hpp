#pragma once
// DeviceHandle: the one move-only owner of a Vulkan object created from a VkDevice. The
// named wrappers (Buffer, Fence, ComputePipeline, ...) hold one, so the destroy-once and
// move logic is written here only. It keeps the vkDestroyXxx (or vkFreeMemory) to call:
//   fence_ = DeviceHandle<VkFence>(device, fence, vkDestroyFence);
#include <utility>

#include "gpu/vulkan_api.hpp"

namespace ts::gpu {

template <typename Handle>
class DeviceHandle {
public:
    using Destroy = void(VKAPI_PTR*)(VkDevice, Handle, const VkAllocationCallbacks*);

    DeviceHandle() = default;
    DeviceHandle(VkDevice device, Handle handle, Destroy destroy) : device_(device), handle_(handle), destroy_(destroy) {}
    ~DeviceHandle() { reset(); }

    DeviceHandle(const DeviceHandle&) = delete;
    DeviceHandle& operator=(const DeviceHandle&) = delete;
    DeviceHandle(DeviceHandle&& other) noexcept
        : device_(other.device_), handle_(std::exchange(other.handle_, VK_NULL_HANDLE)), destroy_(other.destroy_) {}
    DeviceHandle& operator=(DeviceHandle&& other) noexcept {
        if (this != &other) {
            reset();
            device_ = other.device_;
            handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
            destroy_ = other.destroy_;
        }
        return *this;
    }

    Handle get() const { return handle_; }
    VkDevice device() const { return device_; }
    explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

    void reset() {
        if (handle_ != VK_NULL_HANDLE) destroy_(device_, handle_, nullptr);
        handle_ = VK_NULL_HANDLE;
    }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    Handle handle_ = VK_NULL_HANDLE;
    Destroy destroy_ = nullptr;
};

}  // namespace ts::gpu
