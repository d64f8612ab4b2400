#include "gpu/fly/fly_renderer.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>

#include "gpu/fly/graphics_pipeline.hpp"
#include "gpu/vk_check.hpp"

namespace ts::gpu {

// fly_patch.glsl's Patch block: the patch, and where its heights and radiance are read (the
// overview's texels first in each buffer, then the atlas's slots).
struct PatchPush {
    float col0, row0, spacing, morph_start_m, morph_end_m;
    std::uint32_t quads;
    std::int32_t base, stride;
    float origin_col, origin_row, inv_scale;
    std::int32_t fade;
    std::int32_t dims_x, dims_y;
};
static_assert(sizeof(PatchPush) == 56, "fly_patch.glsl's Patch block");

namespace {

constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
constexpr VkShaderStageFlags kStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr int kBindings = 8;



// Copies `bytes` into a device-local buffer at `offset` (the device idle: one submit and wait).
void copy_into(const Context& ctx, const Buffer& target, std::size_t offset, const void* data, std::size_t bytes) {
    Buffer staging = ctx.create_buffer(bytes, MemoryKind::host_visible);
    std::memcpy(staging.mapped(), data, bytes);
    CommandPool pool(ctx.vk_device(), ctx.device().queue_family());
    CommandBuffer cmd(ctx.vk_device(), pool);
    cmd.begin();
    VkBufferCopy region{0, VkDeviceSize(offset), VkDeviceSize(bytes)};
    vkCmdCopyBuffer(cmd.get(), staging.get(), target.get(), 1, &region);
    cmd.end();
    Fence fence(ctx.vk_device());
    submit_and_wait(ctx.device().queue(), cmd.get(), fence);
}

Buffer zeroed(const Context& ctx, std::size_t bytes) {
    Buffer b = ctx.create_buffer(std::max<std::size_t>(bytes, 16), MemoryKind::host_visible);
    std::memset(b.mapped(), 0, b.size());
    return b;
}

Buffer upload(const Context& ctx, const void* data, std::size_t bytes, VkBufferUsageFlags usage) {
    Buffer target(ctx.device(), bytes, MemoryKind::device_local, usage);
    copy_into(ctx, target, 0, data, bytes);
    return target;
}

DeviceHandle<VkRenderPass> make_render_pass(VkDevice device) {
    std::array<VkAttachmentDescription, 2> attachments{};
    attachments[0].format = kColorFormat;
    attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;  // terrain and sky cover every pixel
    attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachments[0].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    attachments[1].format = kDepthFormat;
    attachments[1].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[1].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_STORE;  // read back by tests (coverage)
    attachments[1].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[1].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[1].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachments[1].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    VkAttachmentReference color_ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkAttachmentReference depth_ref{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &color_ref;
    subpass.pDepthStencilAttachment = &depth_ref;
    // The previous frame's blit or copy read the colour target, and its depth test wrote the
    // depth buffer: both finish before this frame writes them again.
    std::array<VkSubpassDependency, 3> dependencies{};
    dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[0].dstSubpass = 0;
    dependencies[0].srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependencies[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependencies[0].srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    dependencies[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    dependencies[1].srcSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[1].dstSubpass = 0;
    dependencies[1].srcStageMask = VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependencies[1].dstStageMask = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT;
    dependencies[1].srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    dependencies[1].dstAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
    // And the blit or copy after the pass reads what it wrote.
    dependencies[2].srcSubpass = 0;
    dependencies[2].dstSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[2].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    dependencies[2].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependencies[2].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    dependencies[2].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    VkRenderPassCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
    info.attachmentCount = std::uint32_t(attachments.size());
    info.pAttachments = attachments.data();
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = std::uint32_t(dependencies.size());
    info.pDependencies = dependencies.data();
    VkRenderPass pass = VK_NULL_HANDLE;
    check(vkCreateRenderPass(device, &info, nullptr, &pass), "vkCreateRenderPass");
    return {device, pass, vkDestroyRenderPass};
}

}  // namespace

std::vector<std::uint32_t> patch_indices(int n) {
    std::vector<std::uint32_t> out;
    out.reserve(std::size_t(6 * n * n));
    const int half = n / 2;
    const auto v = [n](int i, int j) { return std::uint32_t(i + j * (n + 1)); };
    for (int q = 0; q < 4; ++q) {
        const int i0 = (q & 1) * half, j0 = (q >> 1) * half;
        for (int j = j0; j < j0 + half; ++j)
            for (int i = i0; i < i0 + half; ++i) {
                out.insert(out.end(), {v(i, j), v(i + 1, j), v(i + 1, j + 1)});
                out.insert(out.end(), {v(i, j), v(i + 1, j + 1), v(i, j + 1)});
            }
    }
    return out;
}

FlyRenderer::FlyRenderer(const Context& context, const FlyTerrain& terrain, int width, int height)
    : context_(context),
      grid_width_(terrain.width),
      grid_height_(terrain.height),
      patch_quads_(terrain.patch_quads),
      overview_texels_(terrain.overview_width * terrain.overview_height),
      overview_width_(terrain.overview_width),
      overview_height_(terrain.overview_height),
      overview_scale_(terrain.overview_scale),
      detail_levels_(terrain.detail_levels),
      atlas_samples_(terrain.atlas_samples),
      atlas_slots_(terrain.atlas_slots),
      width_(width),
      height_(height) {
    const VkDevice device = context.vk_device();
    const std::size_t atlas = std::size_t(atlas_slots_) * std::size_t(atlas_samples_) * std::size_t(atlas_samples_);
    {
        // The overview's heights, then the atlas's slots (filled by set_tile).
        std::vector<float> all(std::size_t(overview_texels_) + atlas, 0.0f);
        std::copy(terrain.heights.begin(), terrain.heights.end(), all.begin());
        heights_ = upload(context, all.data(), all.size() * sizeof(float), 0);
    }
    rows_ = upload(context, terrain.rows.data(), terrain.rows.size_bytes(), 0);
    const std::vector<std::uint32_t> indices = patch_indices(patch_quads_);
    quadrant_indices_ = std::uint32_t(indices.size() / 4);
    indices_ = upload(context, indices.data(), indices.size() * sizeof(std::uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    frame_ = context.create_buffer(sizeof(FlyFrameUniforms), MemoryKind::host_visible);
    radiance_ = zeroed(context, (std::size_t(overview_texels_) + atlas) * 8);
    sun_radiance_ = zeroed(context, 2 * radiance_.size());
    spheres_ = zeroed(context, 16);
    sky_ = zeroed(context, 16);
    aircraft_ = zeroed(context, 16);

    set_layout_ = DescriptorSetLayout(device, kBindings, kStages);
    pool_ = DescriptorPool(device, 1, kBindings);
    set_ = pool_.allocate(set_layout_.get(), kBindings);
    write_descriptors();
    sky_layout_ = PipelineLayout(device, set_layout_.get(), 0, kStages);
    terrain_layout_ = PipelineLayout(device, set_layout_.get(), sizeof(PatchPush), kStages);
    render_pass_ = make_render_pass(device);
    sky_pipeline_ = make_graphics_pipeline(device, sky_layout_.get(), render_pass_.get(), "fly_sky.vert", "fly_sky.frag",
                                           PipelineDepth::behind);
    terrain_pipeline_ =
        make_graphics_pipeline(device, terrain_layout_.get(), render_pass_.get(), "fly_terrain.vert", "fly_terrain.frag",
                               PipelineDepth::nearest);
    terrain_fade_pipeline_ = make_graphics_pipeline(device, terrain_layout_.get(), render_pass_.get(), "fly_terrain.vert",
                                                    "fly_terrain_fade.frag", PipelineDepth::nearest);
    aircraft_layout_ = PipelineLayout(device, set_layout_.get(), sizeof(glm::mat4), VK_SHADER_STAGE_VERTEX_BIT);
    aircraft_pipeline_ = make_graphics_pipeline(device, aircraft_layout_.get(), render_pass_.get(), "fly_aircraft.vert",
                                                "fly_aircraft.frag", PipelineDepth::nearest);
    hud_ = HudOverlay(context, render_pass_.get());
    command_pool_ = CommandPool(device, context.device().queue_family());
    commands_ = CommandBuffer(device, command_pool_);
    fence_ = Fence(device);
    create_targets();
}

FlyRenderer::~FlyRenderer() { context_.device().wait_idle(); }

void FlyRenderer::write_descriptors() {
    const VkBuffer buffers[kBindings] = {frame_.get(), heights_.get(),  rows_.get(),         radiance_.get(),
                                         sky_.get(),   aircraft_.get(), sun_radiance_.get(), spheres_.get()};
    write_storage_buffers(context_.vk_device(), set_, buffers);
}

void FlyRenderer::create_targets() {
    const VkDevice device = context_.vk_device();
    framebuffer_.reset();
    color_ = GpuImage(context_.device(), std::uint32_t(width_), std::uint32_t(height_), kColorFormat,
                      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    depth_ = GpuImage(context_.device(), std::uint32_t(width_), std::uint32_t(height_), kDepthFormat,
                      VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                      VK_IMAGE_ASPECT_DEPTH_BIT);
    const VkImageView views[2] = {color_.view(), depth_.view()};
    VkFramebufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
    info.renderPass = render_pass_.get();
    info.attachmentCount = 2;
    info.pAttachments = views;
    info.width = std::uint32_t(width_);
    info.height = std::uint32_t(height_);
    info.layers = 1;
    VkFramebuffer fb = VK_NULL_HANDLE;
    check(vkCreateFramebuffer(device, &info, nullptr, &fb), "vkCreateFramebuffer");
    framebuffer_ = {device, fb, vkDestroyFramebuffer};
    readback_ = context_.create_buffer(std::size_t(width_) * std::size_t(height_) * 4, MemoryKind::host_visible);
    depth_readback_ = context_.create_buffer(std::size_t(width_) * std::size_t(height_) * 4, MemoryKind::host_visible);
}

void FlyRenderer::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    width_ = width, height_ = height;
    create_targets();
}

PatchPush FlyRenderer::patch_push(const fly::CdlodPatch& p) const {
    PatchPush push{};
    push.col0 = p.col0, push.row0 = p.row0, push.spacing = p.spacing;
    push.morph_start_m = p.morph_start_m, push.morph_end_m = p.morph_end_m;
    push.quads = std::uint32_t(patch_quads_);
    if (p.slot >= 0) {
        push.base = overview_texels_ + p.slot * atlas_samples_ * atlas_samples_;
        push.stride = atlas_samples_;
        push.origin_col = p.tile_col0, push.origin_row = p.tile_row0, push.inv_scale = 1.0f;
        push.fade = p.level + 1 == detail_levels_ ? 1 : 0;
        // An edge tile holds fewer samples: up to the grid's last texel.
        push.dims_x = std::min(atlas_samples_, grid_width_ - int(p.tile_col0));
        push.dims_y = std::min(atlas_samples_, grid_height_ - int(p.tile_row0));
    } else {
        push.base = 0;
        push.stride = overview_width_;
        push.inv_scale = 1.0f / float(overview_scale_);
        push.dims_x = overview_width_, push.dims_y = overview_height_;
    }
    return push;
}

void FlyRenderer::set_tile(int slot, int sx, int sy, std::span<const float> heights,
                           std::span<const std::uint32_t> radiance, std::span<const std::uint32_t> sun) {
    if (slot < 0 || slot >= atlas_slots_ || sx > atlas_samples_ || sy > atlas_samples_ ||
        heights.size() != std::size_t(sx) * std::size_t(sy) || radiance.size() != 2 * heights.size() ||
        sun.size() != 2 * radiance.size())
        throw std::logic_error("FlyRenderer::set_tile: wrong slot or size");
    const std::size_t stride = std::size_t(atlas_samples_);
    const std::size_t base = std::size_t(overview_texels_) + std::size_t(slot) * stride * stride;
    std::vector<float> rows(stride * std::size_t(sy), 0.0f);
    auto* l = reinterpret_cast<std::uint32_t*>(radiance_.mapped());
    auto* s = reinterpret_cast<std::uint32_t*>(sun_radiance_.mapped());
    for (int r = 0; r < sy; ++r) {
        const std::size_t to = std::size_t(r) * stride, from = std::size_t(r) * std::size_t(sx);
        std::copy_n(heights.data() + from, sx, rows.data() + to);
        std::memcpy(l + 2 * (base + to), radiance.data() + 2 * from, std::size_t(sx) * 8);
        std::memcpy(s + 4 * (base + to), sun.data() + 4 * from, std::size_t(sx) * 16);
    }
    copy_into(context_, heights_, base * sizeof(float), rows.data(), rows.size() * sizeof(float));
}

void FlyRenderer::set_radiance(std::span<const std::uint32_t> packed) {
    if (packed.size_bytes() != std::size_t(overview_texels_) * 8) throw std::logic_error("FlyRenderer::set_radiance: wrong size");
    std::memcpy(radiance_.mapped(), packed.data(), packed.size_bytes());
}

void FlyRenderer::set_sun_radiance(std::span<const std::uint32_t> packed) {
    if (packed.size_bytes() != std::size_t(overview_texels_) * 16)
        throw std::logic_error("FlyRenderer::set_sun_radiance: wrong size");
    std::memcpy(sun_radiance_.mapped(), packed.data(), packed.size_bytes());
}

void FlyRenderer::set_aircraft_spheres(std::span<const glm::vec4> spheres) {
    if (spheres.size_bytes() > spheres_.size()) {
        context_.device().wait_idle();
        spheres_ = context_.create_buffer(spheres.size_bytes(), MemoryKind::host_visible);
        write_descriptors();
    }
    if (!spheres.empty()) std::memcpy(spheres_.mapped(), spheres.data(), spheres.size_bytes());
}

void FlyRenderer::set_sky(std::span<const glm::vec4> table) {
    if (table.size_bytes() != sky_.size()) {
        sky_ = context_.create_buffer(table.size_bytes(), MemoryKind::host_visible);
        write_descriptors();
    }
    std::memcpy(sky_.mapped(), table.data(), table.size_bytes());
}

void FlyRenderer::set_aircraft(std::span<const glm::vec4> vertices) {
    context_.device().wait_idle();
    aircraft_vertices_ = std::uint32_t(vertices.size() / 3);
    aircraft_ = context_.create_buffer(std::max<std::size_t>(vertices.size_bytes(), 16), MemoryKind::host_visible);
    if (!vertices.empty()) std::memcpy(aircraft_.mapped(), vertices.data(), vertices.size_bytes());
    write_descriptors();
}

void FlyRenderer::set_aircraft_transform(const glm::mat4& model_to_eye_relative, bool draw) {
    aircraft_transform_ = model_to_eye_relative;
    draw_aircraft_ = draw && aircraft_vertices_ > 0;
}

void FlyRenderer::record(VkCommandBuffer cmd, const FlyFrameUniforms& frame, const std::vector<fly::CdlodPatch>& patches) {
    std::memcpy(frame_.mapped(), &frame, sizeof frame);
    hud_.record_upload(cmd);
    VkClearValue clears[2]{};
    clears[1].depthStencil = {0.0f, 0};  // reversed Z: 0 is infinitely far
    VkRenderPassBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
    begin.renderPass = render_pass_.get();
    begin.framebuffer = framebuffer_.get();
    begin.renderArea = {{0, 0}, {std::uint32_t(width_), std::uint32_t(height_)}};
    begin.clearValueCount = 2;
    begin.pClearValues = clears;
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    const VkViewport viewport{0.0f, 0.0f, float(width_), float(height_), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {std::uint32_t(width_), std::uint32_t(height_)}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, terrain_pipeline_.get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, terrain_layout_.get(), 0, 1, &set_, 0, nullptr);
    vkCmdBindIndexBuffer(cmd, indices_.get(), 0, VK_INDEX_TYPE_UINT32);
    // The patches of a tile's coarsest level last, with the pipeline that fades to the overview.
    for (int fade = 0; fade < 2; ++fade) {
        if (fade == 1) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, terrain_fade_pipeline_.get());
        for (const fly::CdlodPatch& p : patches) {
            const PatchPush push = patch_push(p);
            if (push.fade != fade) continue;
            vkCmdPushConstants(cmd, terrain_layout_.get(), kStages, 0, sizeof push, &push);
            const std::uint32_t first = p.quadrant < 0 ? 0 : std::uint32_t(p.quadrant) * quadrant_indices_;
            const std::uint32_t count = p.quadrant < 0 ? 4 * quadrant_indices_ : quadrant_indices_;
            vkCmdDrawIndexed(cmd, count, 1, first, 0, 0);
        }
    }
    if (draw_aircraft_) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, aircraft_pipeline_.get());
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, aircraft_layout_.get(), 0, 1, &set_, 0, nullptr);
        vkCmdPushConstants(cmd, aircraft_layout_.get(), VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4),
                           &aircraft_transform_);
        vkCmdDraw(cmd, aircraft_vertices_, 1, 0, 0);
    }
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, sky_pipeline_.get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, sky_layout_.get(), 0, 1, &set_, 0, nullptr);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    hud_.record_draw(cmd, width_, height_);
    vkCmdEndRenderPass(cmd);
}

void FlyRenderer::render_to_memory(const FlyFrameUniforms& frame, const std::vector<fly::CdlodPatch>& patches,
                                   std::vector<std::uint8_t>& rgba, std::vector<float>* depth) {
    commands_.reset();
    commands_.begin();
    record(commands_.get(), frame, patches);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {std::uint32_t(width_), std::uint32_t(height_), 1};
    vkCmdCopyImageToBuffer(commands_.get(), color_.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.get(), 1, &region);
    if (depth != nullptr) {
        VkBufferImageCopy depth_region = region;
        depth_region.imageSubresource.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
        vkCmdCopyImageToBuffer(commands_.get(), depth_.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               depth_readback_.get(), 1, &depth_region);
    }
    VkBufferMemoryBarrier to_host{};
    to_host.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER;
    to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    to_host.srcQueueFamilyIndex = to_host.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    to_host.buffer = readback_.get();
    to_host.size = VK_WHOLE_SIZE;
    VkBufferMemoryBarrier depth_to_host = to_host;
    depth_to_host.buffer = depth_readback_.get();
    const VkBufferMemoryBarrier barriers[2] = {to_host, depth_to_host};
    vkCmdPipelineBarrier(commands_.get(), VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr,
                         depth != nullptr ? 2 : 1, barriers, 0, nullptr);
    commands_.end();
    submit_and_wait(context_.device().queue(), commands_.get(), fence_);
    rgba.resize(std::size_t(width_) * std::size_t(height_) * 4);
    std::memcpy(rgba.data(), readback_.mapped(), rgba.size());
    if (depth != nullptr) {
        depth->resize(std::size_t(width_) * std::size_t(height_));
        std::memcpy(depth->data(), depth_readback_.mapped(), depth->size() * sizeof(float));
    }
}

}  // namespace ts::gpu
