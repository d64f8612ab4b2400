#include "gpu/fly/hud_overlay.hpp"

#include <algorithm>
#include <cstring>

#include "gpu/fly/graphics_pipeline.hpp"
#include "gpu/vk_check.hpp"

namespace ts::gpu {
namespace {

constexpr VkFormat kFormat = VK_FORMAT_R8G8B8A8_UNORM;

struct HudPush {
    std::int32_t origin[2];
    std::int32_t size[2];
    float target[2];
};

// Grown in steps so a line getting one character longer does not make a new image each time.
int round_up(int v, int step) { return (v + step - 1) / step * step; }

}  // namespace

HudOverlay::HudOverlay(const Context& context, VkRenderPass pass) : context_(&context) {
    const VkDevice device = context.vk_device();
    VkSamplerCreateInfo sampler{};
    sampler.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
    sampler.magFilter = sampler.minFilter = VK_FILTER_NEAREST;
    sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sampler.addressModeU = sampler.addressModeV = sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sampler.maxLod = 0.0f;
    VkSampler s = VK_NULL_HANDLE;
    check(vkCreateSampler(device, &sampler, nullptr, &s), "vkCreateSampler");
    sampler_ = {device, s, vkDestroySampler};

    VkDescriptorSetLayoutBinding binding{};
    binding.binding = 0;
    binding.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    binding.descriptorCount = 1;
    binding.stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
    VkDescriptorSetLayoutCreateInfo set_info{};
    set_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    set_info.bindingCount = 1;
    set_info.pBindings = &binding;
    VkDescriptorSetLayout l = VK_NULL_HANDLE;
    check(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &l), "vkCreateDescriptorSetLayout");
    set_layout_ = {device, l, vkDestroyDescriptorSetLayout};

    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
    VkDescriptorPoolCreateInfo pool_info{};
    pool_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = 1;
    pool_info.pPoolSizes = &size;
    VkDescriptorPool p = VK_NULL_HANDLE;
    check(vkCreateDescriptorPool(device, &pool_info, nullptr, &p), "vkCreateDescriptorPool");
    pool_ = {device, p, vkDestroyDescriptorPool};
    VkDescriptorSetAllocateInfo allocate{};
    allocate.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    allocate.descriptorPool = p;
    allocate.descriptorSetCount = 1;
    allocate.pSetLayouts = &l;
    check(vkAllocateDescriptorSets(device, &allocate, &set_), "vkAllocateDescriptorSets");

    layout_ = PipelineLayout(device, l, sizeof(HudPush), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
    pipeline_ = make_graphics_pipeline(device, layout_.get(), pass, "fly_hud.vert", "fly_hud.frag",
                                       PipelineDepth::overlay);
}

void HudOverlay::grow(int width, int height) {
    capacity_w_ = std::max(capacity_w_, round_up(width, 64));
    capacity_h_ = std::max(capacity_h_, round_up(height, 16));
    // The old image may still be bound in a recorded frame: the device finishes it first.
    context_->device().wait_idle();
    image_ = GpuImage(context_->device(), std::uint32_t(capacity_w_), std::uint32_t(capacity_h_), kFormat,
                      VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    staging_ = context_->create_buffer(std::size_t(capacity_w_) * std::size_t(capacity_h_) * 4, MemoryKind::host_visible);
    layout_now_ = VK_IMAGE_LAYOUT_UNDEFINED;
    VkDescriptorImageInfo info{sampler_.get(), image_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet write{};
    write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    write.dstSet = set_;
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &info;
    vkUpdateDescriptorSets(context_->vk_device(), 1, &write, 0, nullptr);
}

void HudOverlay::set(const fly::HudImage& image, int x, int y) {
    if (image.width <= 0 || image.height <= 0) {
        visible_ = false;
        return;
    }
    const std::size_t bytes = std::size_t(image.width) * std::size_t(image.height) * 4;
    // The staging buffer still holds the last overlay: an unchanged one is not copied again.
    const bool uploaded = pending_ || layout_now_ == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    if (uploaded && image.width == width_ && image.height == height_ && x == x_ && y == y_ &&
        std::memcmp(staging_.mapped(), image.rgba.data(), bytes) == 0) {
        visible_ = true;
        return;
    }
    if (image.width > capacity_w_ || image.height > capacity_h_) grow(image.width, image.height);
    // Rows packed tightly: the copy's buffer layout is the overlay's own width.
    std::memcpy(staging_.mapped(), image.rgba.data(), bytes);
    width_ = image.width, height_ = image.height, x_ = x, y_ = y;
    pending_ = true;
    visible_ = true;
}

void HudOverlay::record_upload(VkCommandBuffer cmd) {
    if (!pending_) return;
    // The previous frame's fragment shader read it (finished: one frame in flight, but the
    // layout changes and the order is stated for the validation layer).
    transition_image(cmd, image_.get(), VK_IMAGE_ASPECT_COLOR_BIT, layout_now_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     0, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                     VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {std::uint32_t(width_), std::uint32_t(height_), 1};
    vkCmdCopyBufferToImage(cmd, staging_.get(), image_.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    transition_image(cmd, image_.get(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
    layout_now_ = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    pending_ = false;
}

void HudOverlay::record_draw(VkCommandBuffer cmd, int target_width, int target_height) const {
    if (!visible_ || layout_now_ != VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL) return;
    // Clipped to the target: a window narrower than the text shows its left part.
    const int w = std::min(width_, target_width - x_), h = std::min(height_, target_height - y_);
    if (w <= 0 || h <= 0) return;
    const HudPush push{{x_, y_}, {w, h}, {float(target_width), float(target_height)}};
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.get(), 0, 1, &set_, 0, nullptr);
    vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push,
                       &push);
    vkCmdDraw(cmd, 6, 1, 0, 0);
}

}  // namespace ts::gpu
