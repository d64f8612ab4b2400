#pragma once
// Descriptor set layout, pool and sets for kernels whose resources are all storage buffers,
// bound at consecutive bindings 0..n-1 of set 0 (the convention of every gpu/shaders/*.comp).
#include <cstdint>
#include <span>

#include "gpu/vulkan_api.hpp"

#include "gpu/handle.hpp"

namespace ts::gpu {

class DescriptorSetLayout {
public:
    DescriptorSetLayout() = default;
    // `stages`: the shader stages that see the buffers (compute kernels by default).
    DescriptorSetLayout(VkDevice device, std::uint32_t storage_buffers,
                        VkShaderStageFlags stages = VK_SHADER_STAGE_COMPUTE_BIT);
    VkDescriptorSetLayout get() const { return layout_.get(); }

private:
    DeviceHandle<VkDescriptorSetLayout> layout_;
};

// A pool for up to max_sets sets holding max_storage_buffers descriptors in all. Sets are not
// freed one by one: they go when the pool goes, so a VkDescriptorSet needs no owner of its own.
class DescriptorPool {
public:
    DescriptorPool() = default;
    DescriptorPool(VkDevice device, std::uint32_t max_sets, std::uint32_t max_storage_buffers);

    VkDescriptorPool get() const { return pool_.get(); }
    bool can_allocate(std::uint32_t storage_buffers) const {
        return sets_left_ > 0 && storage_buffers <= descriptors_left_;
    }
    // Throws std::logic_error unless can_allocate(storage_buffers).
    VkDescriptorSet allocate(VkDescriptorSetLayout layout, std::uint32_t storage_buffers);

private:
    DeviceHandle<VkDescriptorPool> pool_;
    std::uint32_t sets_left_ = 0;
    std::uint32_t descriptors_left_ = 0;
};

// Points bindings 0..n-1 of `set` at the whole of each buffer (storage buffers, in order).
void write_storage_buffers(VkDevice device, VkDescriptorSet set, std::span<const VkBuffer> buffers);

}  // namespace ts::gpu
