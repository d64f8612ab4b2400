#include "gpu/batch.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/util/stopwatch.hpp"
#include "gpu/vk_check.hpp"

namespace ts::gpu {
namespace {

// Descriptor pools grow in chunks of this many sets: one per dispatch, reused after submit.
constexpr std::uint32_t kSetsPerPool = 64;
constexpr std::uint32_t kBuffersPerSetGuess = 8;

std::uint32_t group_count(std::uint64_t items, std::uint32_t local_size) {
    if (local_size == 0) throw std::invalid_argument("gpu::groups_for: local size 0");
    const std::uint64_t groups = (items + local_size - 1) / local_size;
    if (groups > UINT32_MAX) throw std::invalid_argument("gpu::groups_for: too many groups");
    return static_cast<std::uint32_t>(groups);
}

}  // namespace

Groups groups_for(std::uint64_t items, std::uint32_t local_size) { return {group_count(items, local_size), 1, 1}; }

Groups groups_for(std::uint64_t width, std::uint64_t height, std::uint32_t local_x, std::uint32_t local_y) {
    return {group_count(width, local_x), group_count(height, local_y), 1};
}

Batch::Batch(const Context& context)
    : context_(context),
      pool_(context.vk_device(), context.device().queue_family()),
      commands_(context.vk_device(), pool_),
      fence_(context.vk_device()) {
    if (context.device_info().timestamp_valid_bits > 0) {
        VkQueryPoolCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
        info.queryType = VK_QUERY_TYPE_TIMESTAMP;
        info.queryCount = kMaxMarks + 1;  // one at the start, one per mark
        VkQueryPool pool = VK_NULL_HANDLE;
        check(vkCreateQueryPool(context.vk_device(), &info, nullptr, &pool), "vkCreateQueryPool");
        timestamps_ = {context.vk_device(), pool, vkDestroyQueryPool};
    }
}

Batch::~Batch() = default;

void Batch::begin_if_needed() {
    if (recording_) return;
    commands_.begin();
    recording_ = true;
    if (timestamps_) {
        vkCmdResetQueryPool(commands_.get(), timestamps_.get(), 0, kMaxMarks + 1);
        vkCmdWriteTimestamp(commands_.get(), VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps_.get(), 0);
    }
}

void Batch::mark(std::string label) {
    if (mark_labels_.size() >= kMaxMarks) throw std::length_error("gpu::Batch::mark: more than 63 marks in one batch");
    begin_if_needed();
    mark_labels_.push_back(std::move(label));
    // Bottom of pipe: written once every command recorded before it has finished.
    if (timestamps_) {
        vkCmdWriteTimestamp(commands_.get(), VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps_.get(),
                            static_cast<std::uint32_t>(mark_labels_.size()));
    }
}

// Every write before (transfer or shader) is made visible to every read or write after.
void Batch::barrier_before_next_command() {
    if (!any_command_) {
        any_command_ = true;
        return;
    }
    VkMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT |
                            VK_ACCESS_TRANSFER_WRITE_BIT;
    const VkPipelineStageFlags stages = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    vkCmdPipelineBarrier(commands_.get(), stages, stages, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

void Batch::check_range(const Buffer& buffer, VkDeviceSize offset, VkDeviceSize bytes, const char* what) const {
    if (offset > buffer.size() || bytes > buffer.size() - offset) {
        throw std::out_of_range(std::string("gpu::Batch::") + what + ": " + std::to_string(bytes) + " bytes at offset " +
                                std::to_string(offset) + " do not fit a buffer of " + std::to_string(buffer.size()));
    }
}

void Batch::upload(const Buffer& dst, std::span<const std::byte> bytes, VkDeviceSize offset) {
    check_range(dst, offset, bytes.size(), "upload");
    if (bytes.empty()) return;
    auto staging = std::make_unique<Buffer>(context_.device(), bytes.size(), MemoryKind::host_visible);
    std::memcpy(staging->mapped(), bytes.data(), bytes.size());  // visible to the device at submit
    begin_if_needed();
    barrier_before_next_command();
    VkBufferCopy region{0, offset, bytes.size()};
    vkCmdCopyBuffer(commands_.get(), staging->get(), dst.get(), 1, &region);
    uploads_.push_back(std::move(staging));
}

void Batch::copy(const Buffer& src, const Buffer& dst, VkDeviceSize bytes, VkDeviceSize src_offset,
                 VkDeviceSize dst_offset) {
    if (bytes == VK_WHOLE_SIZE) bytes = src_offset <= src.size() ? src.size() - src_offset : 0;
    check_range(src, src_offset, bytes, "copy (source)");
    check_range(dst, dst_offset, bytes, "copy (destination)");
    if (bytes == 0) return;
    begin_if_needed();
    barrier_before_next_command();
    VkBufferCopy region{src_offset, dst_offset, bytes};
    vkCmdCopyBuffer(commands_.get(), src.get(), dst.get(), 1, &region);
}

void Batch::fill(const Buffer& dst, std::uint32_t word) {
    if (dst.size() % 4 != 0) throw std::invalid_argument("gpu::Batch::fill: buffer size is not a multiple of 4");
    if (dst.size() == 0) return;
    begin_if_needed();
    barrier_before_next_command();
    vkCmdFillBuffer(commands_.get(), dst.get(), 0, dst.size(), word);
}

VkDescriptorSet Batch::allocate_set(const Kernel& kernel) {
    const std::uint32_t needed = std::max<std::uint32_t>(kernel.layout().storage_buffers, 1);
    if (descriptor_pools_.empty() || !descriptor_pools_.back().can_allocate(needed)) {
        descriptor_pools_.emplace_back(context_.vk_device(), kSetsPerPool,
                                       std::max(kSetsPerPool * kBuffersPerSetGuess, needed));
    }
    return descriptor_pools_.back().allocate(kernel.set_layout(), kernel.layout().storage_buffers);
}

void Batch::dispatch(const Kernel& kernel, std::span<const BufferRef> buffers, std::span<const std::byte> push,
                     Groups groups) {
    const KernelLayout& layout = kernel.layout();
    if (buffers.size() != layout.storage_buffers) {
        throw std::invalid_argument("gpu::Batch::dispatch " + kernel.name() + ": " + std::to_string(buffers.size()) +
                                    " buffers given, the kernel binds " + std::to_string(layout.storage_buffers));
    }
    if (push.size() != layout.push_constant_bytes) {
        throw std::invalid_argument("gpu::Batch::dispatch " + kernel.name() + ": " + std::to_string(push.size()) +
                                    " bytes of push constants given, the kernel takes " +
                                    std::to_string(layout.push_constant_bytes));
    }
    const VkPhysicalDeviceLimits& limits = context_.limits();
    const std::uint32_t counts[3] = {groups.x, groups.y, groups.z};
    for (int axis = 0; axis < 3; ++axis) {
        if (counts[axis] > limits.maxComputeWorkGroupCount[axis]) {
            throw std::invalid_argument("gpu::Batch::dispatch " + kernel.name() + ": " + std::to_string(counts[axis]) +
                                        " groups on axis " + std::to_string(axis) + " exceed the device's " +
                                        std::to_string(limits.maxComputeWorkGroupCount[axis]) + " (split the work)");
        }
    }
    if (groups.x == 0 || groups.y == 0 || groups.z == 0) return;  // nothing to run

    std::vector<VkBuffer> handles(buffers.size());
    const VkDescriptorSet set = allocate_set(kernel);
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        const Buffer& buffer = buffers[i].get();
        if (buffer.size() > limits.maxStorageBufferRange) {
            throw std::invalid_argument("gpu::Batch::dispatch " + kernel.name() + ": binding " + std::to_string(i) +
                                        " is " + std::to_string(buffer.size()) +
                                        " bytes, more than the device's storage buffer range " +
                                        std::to_string(limits.maxStorageBufferRange) + " (split the work)");
        }
        handles[i] = buffer.get();
    }
    write_storage_buffers(context_.vk_device(), set, handles);

    begin_if_needed();
    barrier_before_next_command();
    const VkCommandBuffer commands = commands_.get();
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, kernel.pipeline());
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, kernel.pipeline_layout(), 0, 1, &set, 0,
                            nullptr);
    if (!push.empty()) {
        vkCmdPushConstants(commands, kernel.pipeline_layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                           static_cast<std::uint32_t>(push.size()), push.data());
    }
    vkCmdDispatch(commands, groups.x, groups.y, groups.z);
}

void Batch::download(const Buffer& src, std::span<std::byte> destination, VkDeviceSize offset) {
    check_range(src, offset, destination.size(), "download");
    if (destination.empty()) return;
    auto staging = std::make_unique<Buffer>(context_.device(), destination.size(), MemoryKind::host_visible);
    begin_if_needed();
    barrier_before_next_command();
    VkBufferCopy region{offset, 0, destination.size()};
    vkCmdCopyBuffer(commands_.get(), src.get(), staging->get(), 1, &region);
    downloads_.push_back({std::move(staging), destination});
}

void Batch::submit_and_wait() {
    if (!recording_) return;
    // Make the last copies visible to the host reads below.
    VkMemoryBarrier to_host{};
    to_host.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    to_host.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commands_.get(), VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0, nullptr, 0, nullptr);
    commands_.end();
    recording_ = false;

    const Stopwatch watch;
    gpu::submit_and_wait(context_.device().queue(), commands_.get(), fence_);
    last_run_ms_ = watch.milliseconds();

    stage_times_.clear();
    if (!mark_labels_.empty()) {
        std::vector<std::uint64_t> ticks(mark_labels_.size() + 1, 0);
        if (timestamps_) {
            check(vkGetQueryPoolResults(context_.vk_device(), timestamps_.get(), 0,
                                        static_cast<std::uint32_t>(ticks.size()), ticks.size() * sizeof(std::uint64_t),
                                        ticks.data(), sizeof(std::uint64_t),
                                        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                  "vkGetQueryPoolResults");
        }
        const std::uint32_t bits = context_.device_info().timestamp_valid_bits;
        const std::uint64_t mask = bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
        const double ns_per_tick = context_.limits().timestampPeriod;
        for (std::size_t i = 0; i < mark_labels_.size(); ++i) {
            const double ms = timestamps_ ? static_cast<double>((ticks[i + 1] - ticks[i]) & mask) * ns_per_tick * 1e-6
                                          : std::numeric_limits<double>::quiet_NaN();
            stage_times_.push_back({std::move(mark_labels_[i]), ms});
        }
        mark_labels_.clear();
    }

    for (const PendingDownload& download : downloads_) {
        std::memcpy(download.destination.data(), download.staging->mapped(), download.destination.size());
    }
    downloads_.clear();
    uploads_.clear();
    descriptor_pools_.clear();
    commands_.reset();
    any_command_ = false;
}

}  // namespace ts::gpu
