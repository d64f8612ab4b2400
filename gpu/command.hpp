#pragma once
// Command pool, one primary command buffer, and a fence to wait for its completion.
#include <cstdint>
#include <utility>

#include "gpu/vulkan_api.hpp"

#include "gpu/handle.hpp"

namespace ts::gpu {

class CommandPool {
public:
    CommandPool() = default;
    // Buffers from this pool may be reset one by one (a Batch is recorded again after each submit).
    CommandPool(VkDevice device, std::uint32_t queue_family);
    VkCommandPool get() const { return pool_.get(); }

private:
    DeviceHandle<VkCommandPool> pool_;
};

// A primary command buffer, freed back to its pool (which must outlive it).
class CommandBuffer {
public:
    CommandBuffer() = default;
    CommandBuffer(VkDevice device, const CommandPool& pool);
    ~CommandBuffer();
    CommandBuffer(const CommandBuffer&) = delete;
    CommandBuffer& operator=(const CommandBuffer&) = delete;
    CommandBuffer(CommandBuffer&& other) noexcept;
    CommandBuffer& operator=(CommandBuffer&& other) noexcept;

    VkCommandBuffer get() const { return buffer_; }
    void begin();  // one-time submit
    void end();
    void reset();

private:
    void free();

    VkDevice device_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer buffer_ = VK_NULL_HANDLE;
};

class Fence {
public:
    Fence() = default;
    explicit Fence(VkDevice device);
    VkFence get() const { return fence_.get(); }
    void wait() const;  // no timeout: a hung device is reported as VK_ERROR_DEVICE_LOST
    void reset();

private:
    DeviceHandle<VkFence> fence_;
};

// Submits one recorded command buffer to `queue`, waits for `fence` and resets it for reuse.
void submit_and_wait(VkQueue queue, VkCommandBuffer commands, Fence& fence);

}  // namespace ts::gpu
