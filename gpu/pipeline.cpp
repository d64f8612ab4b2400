#include "gpu/pipeline.hpp"

#include <vector>

#include "gpu/vk_check.hpp"

namespace ts::gpu {

ShaderModule::ShaderModule(VkDevice device, std::span<const std::uint32_t> spirv) {
    VkShaderModuleCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    info.codeSize = spirv.size_bytes();
    info.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    check(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule");
    module_ = {device, module, vkDestroyShaderModule};
}

PipelineLayout::PipelineLayout(VkDevice device, VkDescriptorSetLayout set_layout, std::uint32_t push_constant_bytes,
                               VkShaderStageFlags stages) {
    VkPushConstantRange range{};
    range.stageFlags = stages;
    range.offset = 0;
    range.size = push_constant_bytes;
    VkPipelineLayoutCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    info.setLayoutCount = 1;
    info.pSetLayouts = &set_layout;
    info.pushConstantRangeCount = push_constant_bytes > 0 ? 1 : 0;
    info.pPushConstantRanges = push_constant_bytes > 0 ? &range : nullptr;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    check(vkCreatePipelineLayout(device, &info, nullptr, &layout), "vkCreatePipelineLayout");
    layout_ = {device, layout, vkDestroyPipelineLayout};
}

ComputePipeline::ComputePipeline(VkDevice device, VkPipelineLayout layout, const ShaderModule& shader,
                                 std::span<const std::uint32_t> specialization) {
    std::vector<VkSpecializationMapEntry> entries(specialization.size());
    for (std::uint32_t i = 0; i < entries.size(); ++i) {
        entries[i].constantID = i;
        entries[i].offset = i * sizeof(std::uint32_t);
        entries[i].size = sizeof(std::uint32_t);
    }
    VkSpecializationInfo specialization_info{};
    specialization_info.mapEntryCount = static_cast<std::uint32_t>(entries.size());
    specialization_info.pMapEntries = entries.data();
    specialization_info.dataSize = specialization.size_bytes();
    specialization_info.pData = specialization.data();

    VkComputePipelineCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = shader.get();
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = specialization.empty() ? nullptr : &specialization_info;
    info.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    check(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline), "vkCreateComputePipelines");
    pipeline_ = {device, pipeline, vkDestroyPipeline};
}

}  // namespace ts::gpu
