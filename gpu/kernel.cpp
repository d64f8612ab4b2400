#include "gpu/kernel.hpp"

#include <stdexcept>

#include "gpu/spirv.hpp"

namespace ts::gpu {

Kernel::Kernel(const Context& context, std::string_view shader, KernelLayout layout)
    : Kernel(context, std::string(shader), spirv(shader), std::move(layout)) {}

Kernel::Kernel(const Context& context, std::string name, std::span<const std::uint32_t> code, KernelLayout layout)
    : name_(std::move(name)), layout_(std::move(layout)) {
    const std::uint32_t push_limit = context.limits().maxPushConstantsSize;
    if (layout_.push_constant_bytes % 4 != 0 || layout_.push_constant_bytes > push_limit) {
        throw std::invalid_argument("gpu::Kernel " + name_ + ": " + std::to_string(layout_.push_constant_bytes) +
                                    " bytes of push constants (must be a multiple of 4, at most " +
                                    std::to_string(push_limit) + ")");
    }
    const VkDevice device = context.vk_device();
    set_layout_ = DescriptorSetLayout(device, layout_.storage_buffers);
    pipeline_layout_ = PipelineLayout(device, set_layout_.get(), layout_.push_constant_bytes);
    // The module is needed only while the pipeline is built.
    const ShaderModule module(device, code);
    pipeline_ = ComputePipeline(device, pipeline_layout_.get(), module, layout_.specialization);
}

}  // namespace ts::gpu
