#pragma once
// The flythrough's graphics pipelines: no vertex input (shaders build their vertices from
// gl_VertexIndex and storage buffers), triangle lists, dynamic viewport and scissor, one colour
// attachment; what differs between them is how they use depth and whether they blend.
#include "gpu/handle.hpp"
#include "gpu/vulkan_api.hpp"

namespace ts::gpu {

enum class PipelineDepth {
    nearest,  // reversed Z: writes depth, keeps what is nearer (GREATER); terrain, aircraft
    behind,   // only where depth is still the clear value (EQUAL), no write; the sky
    overlay,  // no depth test, alpha-blended over what is there; the HUD
};

// `vertex` and `fragment` name SPIR-V embedded in ts_gpu (gpu/spirv.hpp).
DeviceHandle<VkPipeline> make_graphics_pipeline(VkDevice device, VkPipelineLayout layout, VkRenderPass pass,
                                                const char* vertex, const char* fragment, PipelineDepth depth);

}  // namespace ts::gpu
