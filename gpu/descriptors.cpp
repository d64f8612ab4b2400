#include "gpu/descriptors.hpp"

#include <stdexcept>
#include <vector>

#include "gpu/vk_check.hpp"

namespace ts::gpu {

DescriptorSetLayout::DescriptorSetLayout(VkDevice device, std::uint32_t storage_buffers, VkShaderStageFlags stages) {
    std::vector<VkDescriptorSetLayoutBinding> bindings(storage_buffers);
    for (std::uint32_t i = 0; i < storage_buffers; ++i) {
        bindings[i].binding = i;
        bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        bindings[i].descriptorCount = 1;
        bindings[i].stageFlags = stages;
    }
    VkDescriptorSetLayoutCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    info.bindingCount = storage_buffers;
    info.pBindings = bindings.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    check(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout), "vkCreateDescriptorSetLayout");
    layout_ = {device, layout, vkDestroyDescriptorSetLayout};
}

DescriptorPool::DescriptorPool(VkDevice device, std::uint32_t max_sets, std::uint32_t max_storage_buffers)
    : sets_left_(max_sets), descriptors_left_(max_storage_buffers) {
    VkDescriptorPoolSize size{};
    size.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    size.descriptorCount = max_storage_buffers;
    VkDescriptorPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    info.maxSets = max_sets;
    info.poolSizeCount = 1;
    info.pPoolSizes = &size;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    check(vkCreateDescriptorPool(device, &info, nullptr, &pool), "vkCreateDescriptorPool");
    pool_ = {device, pool, vkDestroyDescriptorPool};
}

VkDescriptorSet DescriptorPool::allocate(VkDescriptorSetLayout layout, std::uint32_t storage_buffers) {
    if (!can_allocate(storage_buffers)) throw std::logic_error("gpu::DescriptorPool: pool exhausted");
    VkDescriptorSetAllocateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    info.descriptorPool = pool_.get();
    info.descriptorSetCount = 1;
    info.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    check(vkAllocateDescriptorSets(pool_.device(), &info, &set), "vkAllocateDescriptorSets");
    sets_left_ -= 1;
    descriptors_left_ -= storage_buffers;
    return set;
}

void write_storage_buffers(VkDevice device, VkDescriptorSet set, std::span<const VkBuffer> buffers) {
    std::vector<VkDescriptorBufferInfo> infos(buffers.size());
    std::vector<VkWriteDescriptorSet> writes(buffers.size());
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        infos[i] = {buffers[i], 0, VK_WHOLE_SIZE};
        writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        writes[i].dstSet = set;
        writes[i].dstBinding = static_cast<std::uint32_t>(i);
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        writes[i].pBufferInfo = &infos[i];
    }
    vkUpdateDescriptorSets(device, static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

}  // namespace ts::gpu
