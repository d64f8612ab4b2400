#pragma once
// The HUD in the frame: core/fly/hud_text.hpp's RGBA8 image in a sampled Vulkan image, copied
// from a staging buffer only when the text changed, and drawn last in the render pass as a
// screen-space quad blended over the terrain and sky (fly_hud.vert|frag).
//
// Like FlyRenderer, it assumes one frame in flight: set() runs while the device is idle.
#include <cstdint>

#include "core/fly/hud_text.hpp"
#include "gpu/buffer.hpp"
#include "gpu/context.hpp"
#include "gpu/fly/gpu_image.hpp"
#include "gpu/handle.hpp"
#include "gpu/pipeline.hpp"

namespace ts::gpu {

class HudOverlay {
public:
    HudOverlay() = default;
    HudOverlay(const Context& context, VkRenderPass pass);

    // The new overlay, its top-left corner at pixel (x, y) of the target; an empty image hides
    // it. The image grows (never shrinks) to hold it; the same pixels at the same place are not
    // copied again.
    void set(const fly::HudImage& image, int x, int y);
    void hide() { visible_ = false; }
    bool visible() const { return visible_; }

    // Outside the render pass, before it: the copy of a changed overlay, if any.
    void record_upload(VkCommandBuffer cmd);
    // Inside the render pass, last: the quad, if visible.
    void record_draw(VkCommandBuffer cmd, int target_width, int target_height) const;

private:
    void grow(int width, int height);

    const Context* context_ = nullptr;
    DeviceHandle<VkSampler> sampler_;
    DeviceHandle<VkDescriptorSetLayout> set_layout_;
    DeviceHandle<VkDescriptorPool> pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    PipelineLayout layout_;
    DeviceHandle<VkPipeline> pipeline_;
    GpuImage image_;
    Buffer staging_;
    int capacity_w_ = 0, capacity_h_ = 0;  // the image's size
    int width_ = 0, height_ = 0, x_ = 0, y_ = 0;  // the overlay's used part and place
    VkImageLayout layout_now_ = VK_IMAGE_LAYOUT_UNDEFINED;
    bool pending_ = false;  // staging holds an overlay not yet copied
    bool visible_ = false;
};

}  // namespace ts::gpu
