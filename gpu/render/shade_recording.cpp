#include "gpu/render/shade_recording.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "gpu/batch.hpp"
#include "gpu/vk_check.hpp"

namespace ts::gpu::render {
namespace {

constexpr VkDeviceSize kLightBytes = 16 * 4 * sizeof(float);


// Host-visible memory the kernel may write and the host read back fast: device-local (no
// copy across a bus) and cached (host reads are not uncached reads of write-combined memory).
bool kernel_writes_host_memory(const Buffer& host) {
    const VkMemoryPropertyFlags wanted = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT | VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
    return (host.memory_properties() & wanted) == wanted;
}

void memory_barrier(VkCommandBuffer commands, VkPipelineStageFlags src_stages, VkAccessFlags src_access,
                    VkPipelineStageFlags dst_stages, VkAccessFlags dst_access) {
    VkMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    barrier.srcAccessMask = src_access;
    barrier.dstAccessMask = dst_access;
    vkCmdPipelineBarrier(commands, src_stages, dst_stages, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

}  // namespace

ShadeRecording::ShadeRecording(const Context& context, const Kernel& shade, std::span<const BandInput> bands,
                               Readback readback)
    : context_(context),
      light_(context.create_buffer(kLightBytes, MemoryKind::host_visible)),
      descriptors_(context.vk_device(), std::uint32_t(std::max<std::size_t>(bands.size(), 1)),
                   std::uint32_t(3 * std::max<std::size_t>(bands.size(), 1))),
      pool_(context.vk_device(), context.device().queue_family()),
      commands_(context.vk_device(), pool_),
      fence_(context.vk_device()) {
    for (const BandInput& in : bands) {
        if (!in.transfer) throw std::invalid_argument("gpu::render::ShadeRecording: null transfer buffer");
        const VkDeviceSize rgb_bytes = padded_to_quads(in.texels) * 3 * sizeof(float);
        Band b{in.first, in.texels, Buffer(), context.create_buffer(rgb_bytes, MemoryKind::host_visible)};
        if (readback == Readback::staging || !kernel_writes_host_memory(b.host_rgb)) b.device_rgb = context.create_buffer(rgb_bytes);
        bands_.push_back(std::move(b));
    }
    if (context.device_info().timestamp_valid_bits > 0) {
        VkQueryPoolCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
        info.queryType = VK_QUERY_TYPE_TIMESTAMP;
        info.queryCount = std::uint32_t(1 + 2 * bands.size());  // the start, then shade and download per band
        VkQueryPool pool = VK_NULL_HANDLE;
        check(vkCreateQueryPool(context.vk_device(), &info, nullptr, &pool), "vkCreateQueryPool");
        timestamps_ = {context.vk_device(), pool, vkDestroyQueryPool};
    }
    record(shade, bands);
}

ShadeRecording::~ShadeRecording() = default;

bool ShadeRecording::reads_directly() const {
    return std::all_of(bands_.begin(), bands_.end(), [](const Band& b) { return !b.device_rgb.get(); });
}

void ShadeRecording::record(const Kernel& shade, std::span<const BandInput> inputs) {
    const VkCommandBuffer commands = commands_.get();
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = 0;  // submitted again every frame (not one-time), never while pending
    check(vkBeginCommandBuffer(commands, &begin), "vkBeginCommandBuffer");
    std::uint32_t query = 0;
    auto mark = [&](const char* label) {
        if (!timestamps_) return;
        vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps_.get(), ++query);
        mark_labels_.push_back(label);
    };
    if (timestamps_) {
        vkCmdResetQueryPool(commands, timestamps_.get(), 0, std::uint32_t(1 + 2 * inputs.size()));
        vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps_.get(), 0);
    }
    // The previous frame's writes and copies (an earlier submit) come before this frame's.
    const VkPipelineStageFlags device_stages = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    memory_barrier(commands, device_stages, VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, device_stages,
                   VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT |
                       VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, shade.pipeline());
    for (std::size_t k = 0; k < bands_.size(); ++k) {
        const Band& b = bands_[k];
        const Buffer& out = b.device_rgb.get() ? b.device_rgb : b.host_rgb;
        const VkDescriptorSet set = descriptors_.allocate(shade.set_layout(), 3);
        const VkBuffer bound[3] = {inputs[k].transfer->get(), light_.get(), out.get()};
        write_storage_buffers(context_.vk_device(), set, bound);
        const std::uint32_t quads = std::uint32_t(padded_to_quads(b.texels) / 4);
        const ShadePush push{quads, quads};
        vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, shade.pipeline_layout(), 0, 1, &set, 0,
                                nullptr);
        vkCmdPushConstants(commands, shade.pipeline_layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
        vkCmdDispatch(commands, groups_for(quads, kShadeGroup).x, 1, 1);
        mark("shade");
        if (b.device_rgb.get()) {
            memory_barrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                           VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
            const VkBufferCopy region{0, 0, b.texels * 3 * sizeof(float)};
            vkCmdCopyBuffer(commands, b.device_rgb.get(), b.host_rgb.get(), 1, &region);
            mark("download");
        }
    }
    // The radiance, written by the kernels or the copies, made visible to the host's reads.
    memory_barrier(commands, device_stages, VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
                   VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
    check(vkEndCommandBuffer(commands), "vkEndCommandBuffer");
}

void ShadeRecording::run(std::span<const float, 64> light, glm::vec3* rgb_out) {
    stages_.clear();
    if (bands_.empty()) return;
    // Coherent memory: the host write is visible to the device at the submit.
    std::memcpy(light_.mapped(), light.data(), kLightBytes);
    submit_and_wait(context_.device().queue(), commands_.get(), fence_);

    for (const Band& b : bands_)
        std::memcpy(static_cast<void*>(rgb_out + b.first), b.host_rgb.mapped(), b.texels * 3 * sizeof(float));

    std::vector<std::uint64_t> ticks(mark_labels_.size() + 1, 0);
    if (timestamps_) {
        check(vkGetQueryPoolResults(context_.vk_device(), timestamps_.get(), 0, std::uint32_t(ticks.size()),
                                    ticks.size() * sizeof(std::uint64_t), ticks.data(), sizeof(std::uint64_t),
                                    VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
              "vkGetQueryPoolResults");
    }
    const std::uint32_t bits = context_.device_info().timestamp_valid_bits;
    const std::uint64_t mask = bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
    const double ns_per_tick = context_.limits().timestampPeriod;
    auto add = [&](const char* label, double ms) {
        auto it = std::find_if(stages_.begin(), stages_.end(), [&](const StageTime& s) { return s.label == label; });
        if (it == stages_.end()) stages_.push_back({label, ms});
        else it->ms += ms;
    };
    if (!timestamps_) add("shade", std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < mark_labels_.size(); ++i)
        add(mark_labels_[i], double((ticks[i + 1] - ticks[i]) & mask) * ns_per_tick * 1e-6);
}

}  // namespace ts::gpu::render
