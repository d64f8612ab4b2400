#pragma once
// Shader module, pipeline layout (one descriptor set, one push-constant block) and compute
// pipeline.
#include <cstdint>
#include <span>

#include "gpu/vulkan_api.hpp"

#include "gpu/handle.hpp"

namespace ts::gpu {

class ShaderModule {
public:
    ShaderModule() = default;
    ShaderModule(VkDevice device, std::span<const std::uint32_t> spirv);
    VkShaderModule get() const { return module_.get(); }

private:
    DeviceHandle<VkShaderModule> module_;
};

class PipelineLayout {
public:
    PipelineLayout() = default;
    // push_constant_bytes may be 0 (no push constants); else a multiple of 4.
    // `stages`: the shader stages that see the push constants.
    PipelineLayout(VkDevice device, VkDescriptorSetLayout set_layout, std::uint32_t push_constant_bytes,
                   VkShaderStageFlags stages = VK_SHADER_STAGE_COMPUTE_BIT);
    VkPipelineLayout get() const { return layout_.get(); }

private:
    DeviceHandle<VkPipelineLayout> layout_;
};

class ComputePipeline {
public:
    ComputePipeline() = default;
    // Entry point "main". specialization[i] sets `layout(constant_id = i) const uint` (e.g. a
    // workgroup size or an azimuth count fixed per pipeline).
    ComputePipeline(VkDevice device, VkPipelineLayout layout, const ShaderModule& shader,
                    std::span<const std::uint32_t> specialization = {});
    VkPipeline get() const { return pipeline_.get(); }

private:
    DeviceHandle<VkPipeline> pipeline_;
};

}  // namespace ts::gpu
