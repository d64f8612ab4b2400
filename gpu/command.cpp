#include "gpu/command.hpp"

#include <limits>

#include "gpu/vk_check.hpp"

namespace ts::gpu {

CommandPool::CommandPool(VkDevice device, std::uint32_t queue_family) {
    VkCommandPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT | VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    info.queueFamilyIndex = queue_family;
    VkCommandPool pool = VK_NULL_HANDLE;
    check(vkCreateCommandPool(device, &info, nullptr, &pool), "vkCreateCommandPool");
    pool_ = {device, pool, vkDestroyCommandPool};
}

CommandBuffer::CommandBuffer(VkDevice device, const CommandPool& pool) : device_(device), pool_(pool.get()) {
    VkCommandBufferAllocateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    info.commandPool = pool_;
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(device, &info, &buffer_), "vkAllocateCommandBuffers");
}

CommandBuffer::~CommandBuffer() { free(); }

CommandBuffer::CommandBuffer(CommandBuffer&& other) noexcept
    : device_(other.device_), pool_(other.pool_), buffer_(std::exchange(other.buffer_, VK_NULL_HANDLE)) {}

CommandBuffer& CommandBuffer::operator=(CommandBuffer&& other) noexcept {
    if (this != &other) {
        free();
        device_ = other.device_;
        pool_ = other.pool_;
        buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    }
    return *this;
}

void CommandBuffer::begin() {
    VkCommandBufferBeginInfo info{};
    info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(buffer_, &info), "vkBeginCommandBuffer");
}

void CommandBuffer::end() { check(vkEndCommandBuffer(buffer_), "vkEndCommandBuffer"); }

void CommandBuffer::reset() { check(vkResetCommandBuffer(buffer_, 0), "vkResetCommandBuffer"); }

void CommandBuffer::free() {
    if (buffer_ != VK_NULL_HANDLE) vkFreeCommandBuffers(device_, pool_, 1, &buffer_);
    buffer_ = VK_NULL_HANDLE;
}

Fence::Fence(VkDevice device) {
    VkFenceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    VkFence fence = VK_NULL_HANDLE;
    check(vkCreateFence(device, &info, nullptr, &fence), "vkCreateFence");
    fence_ = {device, fence, vkDestroyFence};
}

void Fence::wait() const {
    const VkFence fence = fence_.get();
    check(vkWaitForFences(fence_.device(), 1, &fence, VK_TRUE, std::numeric_limits<std::uint64_t>::max()),
          "vkWaitForFences");
}

void Fence::reset() {
    const VkFence fence = fence_.get();
    check(vkResetFences(fence_.device(), 1, &fence), "vkResetFences");
}

void submit_and_wait(VkQueue queue, VkCommandBuffer commands, Fence& fence) {
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    check(vkQueueSubmit(queue, 1, &submit, fence.get()), "vkQueueSubmit");
    fence.wait();
    fence.reset();
}

}  // namespace ts::gpu
