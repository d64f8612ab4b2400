#pragma once
// gpu::Context: everything a compute run needs once per process: the instance (with the
// validation layer and its messenger when asked for), the chosen physical device and the
// logical device with its compute queue. Kernels and Batches are made from it.
//
//   gpu::Context context;                        // default device, TERRASHADE_VALIDATION from env
//   gpu::Context context({.device_index = 1});   // what --device 1 does
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "gpu/buffer.hpp"
#include "gpu/debug_messenger.hpp"
#include "gpu/device.hpp"
#include "gpu/instance.hpp"
#include "gpu/physical_device.hpp"
#include "gpu/validation_log.hpp"

namespace ts::gpu {

struct ContextOptions {
    // --device N: the index terrashade devices prints; empty picks the best device.
    std::optional<std::uint32_t> device_index;
    // VK_LAYER_KHRONOS_validation with every warning and error recorded.
    bool validation = validation_requested_by_environment();
    // Where those messages go; made by the Context if empty. Pass one to read it after the
    // Context is gone (messages at device and instance destruction land there too).
    std::shared_ptr<ValidationLog> validation_log;
    // Extensions a window needs (its surface's on the instance, VK_KHR_swapchain on the device).
    std::vector<std::string> instance_extensions;
    std::vector<std::string> device_extensions;
};

class Context {
public:
    explicit Context(ContextOptions options = {});
    ~Context();
    // Kernels and Batches keep a reference: a Context stays where it was made.
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance vk_instance() const { return instance_.get(); }
    const Device& device() const { return device_; }
    VkDevice vk_device() const { return device_.get(); }
    const PhysicalDeviceInfo& device_info() const { return devices_[device_index_]; }
    const std::vector<PhysicalDeviceInfo>& all_devices() const { return devices_; }
    const VkPhysicalDeviceLimits& limits() const { return device_.limits(); }

    // Bytes in the largest device-local memory heap: what tiling of large DEMs must fit in
    // (an upper bound; other programs share it).
    VkDeviceSize device_local_bytes() const;

    bool validation_enabled() const { return log_ != nullptr; }
    // Warnings and errors the validation layer reported so far (empty without validation).
    std::vector<std::string> validation_messages() const;

    // A buffer on this context's device; see gpu/buffer.hpp.
    Buffer create_buffer(VkDeviceSize bytes, MemoryKind kind = MemoryKind::device_local) const {
        return Buffer(device_, bytes, kind);
    }

private:
    // Member order is destruction order reversed: the device goes before the messenger,
    // the messenger before the instance, and the log last.
    std::shared_ptr<ValidationLog> log_;
    Instance instance_;
    DebugMessenger messenger_;
    std::vector<PhysicalDeviceInfo> devices_;
    std::uint32_t device_index_ = 0;
    Device device_;
};

}  // namespace ts::gpu
