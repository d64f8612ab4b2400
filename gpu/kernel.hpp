#pragma once
// gpu::Kernel: one compute shader made ready to dispatch: its pipeline, and the layout that
// says how many storage buffers it binds (set 0, bindings 0..n-1) and how many bytes of push
// constants it takes. Record dispatches of it with a gpu::Batch.
//
//   gpu::Kernel saxpy(context, "saxpy", {.storage_buffers = 2, .push_constant_bytes = 8});
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gpu/context.hpp"
#include "gpu/descriptors.hpp"
#include "gpu/pipeline.hpp"

namespace ts::gpu {

struct KernelLayout {
    std::uint32_t storage_buffers = 0;
    std::uint32_t push_constant_bytes = 0;  // a multiple of 4, at most limits().maxPushConstantsSize
    std::vector<std::uint32_t> specialization = {};  // constant_id 0, 1, ... (see ComputePipeline)
};

class Kernel {
public:
    // A shader embedded from gpu/shaders ("name" or "name.comp").
    Kernel(const Context& context, std::string_view shader, KernelLayout layout);
    // Any SPIR-V (a test's own shader); name is for messages.
    Kernel(const Context& context, std::string name, std::span<const std::uint32_t> spirv, KernelLayout layout);

    const std::string& name() const { return name_; }
    const KernelLayout& layout() const { return layout_; }
    VkDescriptorSetLayout set_layout() const { return set_layout_.get(); }
    VkPipelineLayout pipeline_layout() const { return pipeline_layout_.get(); }
    VkPipeline pipeline() const { return pipeline_.get(); }

private:
    std::string name_;
    KernelLayout layout_;
    DescriptorSetLayout set_layout_;
    PipelineLayout pipeline_layout_;
    ComputePipeline pipeline_;
};

}  // namespace ts::gpu
