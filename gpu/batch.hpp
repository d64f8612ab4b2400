#pragma once
// gpu::Batch: records uploads, kernel dispatches and downloads into one command buffer, runs
// them with one submit, and hands the downloaded bytes back. Commands run in the order they
// were recorded: the Batch puts a memory barrier between consecutive commands, so a dispatch
// sees what the upload or dispatch before it wrote. (That serialises independent dispatches;
// simple and right is the point here.)
//
//   gpu::Buffer x = context.create_buffer(n * sizeof(float)), y = ...;
//   std::vector<float> result(n);
//   gpu::Batch batch(context);
//   batch.upload(x, std::span<const float>(xs));
//   batch.upload(y, std::span<const float>(ys));
//   batch.dispatch(saxpy, {x, y}, SaxpyPush{2.0f, n}, gpu::groups_for(n, 64));
//   batch.download(y, std::span<float>(result));
//   batch.submit_and_wait();               // result now holds y; the batch is empty again
//
// Not thread-safe: one Batch per thread, and one thread submitting to a Context at a time.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "gpu/buffer.hpp"
#include "gpu/command.hpp"
#include "gpu/context.hpp"
#include "gpu/descriptors.hpp"
#include "gpu/kernel.hpp"

namespace ts::gpu {

// How many workgroups a dispatch runs in each dimension.
struct Groups {
    std::uint32_t x = 1;
    std::uint32_t y = 1;
    std::uint32_t z = 1;
};

// Enough groups of local_size invocations to cover `items` (rounded up).
Groups groups_for(std::uint64_t items, std::uint32_t local_size);
// The same in two dimensions, for an image of width x height and a local_x x local_y group.
Groups groups_for(std::uint64_t width, std::uint64_t height, std::uint32_t local_x, std::uint32_t local_y);

using BufferRef = std::reference_wrapper<const Buffer>;

class Batch {
public:
    explicit Batch(const Context& context);
    ~Batch();
    Batch(const Batch&) = delete;
    Batch& operator=(const Batch&) = delete;

    // Copies bytes into dst at offset when the batch runs (the bytes are staged now: the caller
    // may reuse its memory at once).
    void upload(const Buffer& dst, std::span<const std::byte> bytes, VkDeviceSize offset = 0);
    template <typename T>
    void upload(const Buffer& dst, std::span<const T> values, VkDeviceSize offset = 0) {
        static_assert(std::is_trivially_copyable_v<T>);
        upload(dst, std::as_bytes(values), offset);
    }

    // A new device-local buffer holding values once the batch has run (the upload is recorded).
    template <typename T>
    Buffer upload_new(std::span<const T> values) {
        Buffer buffer = context_.create_buffer(values.size_bytes());
        upload(buffer, values);
        return buffer;
    }

    // Copies bytes from src to dst (whole src by default) on the device.
    void copy(const Buffer& src, const Buffer& dst, VkDeviceSize bytes = VK_WHOLE_SIZE, VkDeviceSize src_offset = 0,
              VkDeviceSize dst_offset = 0);
    // Sets every 32-bit word of dst to `word` (0 clears; a float's bits fill with that float).
    void fill(const Buffer& dst, std::uint32_t word = 0);

    // Runs kernel with buffers bound at bindings 0, 1, ... and the push constants.
    void dispatch(const Kernel& kernel, std::span<const BufferRef> buffers, std::span<const std::byte> push,
                  Groups groups);
    void dispatch(const Kernel& kernel, std::initializer_list<BufferRef> buffers, Groups groups) {
        dispatch(kernel, std::span<const BufferRef>(buffers.begin(), buffers.size()), {}, groups);
    }
    template <typename Push>
    void dispatch(const Kernel& kernel, std::initializer_list<BufferRef> buffers, const Push& push, Groups groups) {
        static_assert(std::is_trivially_copyable_v<Push>);
        dispatch(kernel, std::span<const BufferRef>(buffers.begin(), buffers.size()),
                 std::as_bytes(std::span<const Push, 1>(&push, 1)), groups);
    }

    // Copies src (from offset, destination.size() bytes) into destination when the batch has
    // run: destination must stay valid until submit_and_wait() returns.
    void download(const Buffer& src, std::span<std::byte> destination, VkDeviceSize offset = 0);
    template <typename T>
    void download(const Buffer& src, std::span<T> destination, VkDeviceSize offset = 0) {
        static_assert(std::is_trivially_copyable_v<T> && !std::is_const_v<T>);
        download(src, std::as_writable_bytes(destination), offset);
    }

    // Runs everything recorded, waits, fills the download destinations, and empties the batch
    // for the next use. A no-op when nothing was recorded.
    void submit_and_wait();

    // Wall-clock milliseconds of the last submit_and_wait (submit to fence), for benchmarks.
    double last_run_ms() const { return last_run_ms_; }

    // Per-stage device time: mark("pyramid") after the pyramid's commands, mark("horizons")
    // after the horizons', ...; after submit_and_wait(), stage_times() holds each label with the
    // device milliseconds since the previous mark (the first since the batch began). Without
    // GPU timestamps on the device the milliseconds are NaN. At most kMaxMarks per submit.
    static constexpr std::uint32_t kMaxMarks = 63;
    void mark(std::string label);
    struct StageTime {
        std::string label;
        double ms;
    };
    const std::vector<StageTime>& stage_times() const { return stage_times_; }

private:
    struct PendingDownload {
        std::unique_ptr<Buffer> staging;
        std::span<std::byte> destination;
    };

    void begin_if_needed();
    void barrier_before_next_command();
    VkDescriptorSet allocate_set(const Kernel& kernel);
    void check_range(const Buffer& buffer, VkDeviceSize offset, VkDeviceSize bytes, const char* what) const;

    const Context& context_;
    CommandPool pool_;
    CommandBuffer commands_;
    Fence fence_;
    bool recording_ = false;
    bool any_command_ = false;
    std::vector<DescriptorPool> descriptor_pools_;
    std::vector<std::unique_ptr<Buffer>> uploads_;
    std::vector<PendingDownload> downloads_;
    double last_run_ms_ = 0.0;
    DeviceHandle<VkQueryPool> timestamps_;  // null without GPU timestamps
    std::vector<std::string> mark_labels_;
    std::vector<StageTime> stage_times_;
};

}  // namespace ts::gpu
