#pragma once
// A 2D image with its own memory and one view: the flythrough's colour and depth targets.
#include <cstdint>

#include "gpu/device.hpp"
#include "gpu/handle.hpp"
#include "gpu/vulkan_api.hpp"

namespace ts::gpu {

class GpuImage {
public:
    GpuImage() = default;
    GpuImage(const Device& device, std::uint32_t width, std::uint32_t height, VkFormat format,
             VkImageUsageFlags usage, VkImageAspectFlags aspect);
    VkImage get() const { return image_.get(); }
    VkImageView view() const { return view_.get(); }
    VkFormat format() const { return format_; }

private:
    // Destruction in reverse: the view, then the image, then its memory.
    DeviceHandle<VkDeviceMemory> memory_;
    DeviceHandle<VkImage> image_;
    DeviceHandle<VkImageView> view_;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
};

// A pipeline barrier moving a whole colour (or depth) image between layouts.
void transition_image(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                      VkImageLayout to, VkAccessFlags src_access, VkAccessFlags dst_access,
                      VkPipelineStageFlags src_stage, VkPipelineStageFlags dst_stage);

}  // namespace ts::gpu
