#include "gpu/context.hpp"

#include <algorithm>

namespace ts::gpu {
namespace {

std::shared_ptr<ValidationLog> make_log(const ContextOptions& options) {
    if (!options.validation) return nullptr;
    return options.validation_log ? options.validation_log : std::make_shared<ValidationLog>();
}

Instance make_instance(const std::shared_ptr<ValidationLog>& log, const std::vector<std::string>& extensions) {
    InstanceOptions options;
    options.extensions = extensions;
    options.validation = log != nullptr;
    options.log = log.get();
    return Instance(options);
}

}  // namespace

Context::Context(ContextOptions options)
    : log_(make_log(options)),
      instance_(make_instance(log_, options.instance_extensions)),
      messenger_(log_ ? DebugMessenger(instance_.get(), *log_) : DebugMessenger()),
      devices_(enumerate_physical_devices(instance_.get())),
      device_index_(choose_device(devices_, options.device_index).index),
      device_(devices_[device_index_], options.device_extensions) {}

Context::~Context() = default;

VkDeviceSize Context::device_local_bytes() const {
    const VkPhysicalDeviceMemoryProperties& memory = device_.memory_properties();
    VkDeviceSize largest = 0;
    for (std::uint32_t i = 0; i < memory.memoryHeapCount; ++i) {
        if (memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) {
            largest = std::max(largest, memory.memoryHeaps[i].size);
        }
    }
    return largest;
}

std::vector<std::string> Context::validation_messages() const {
    return log_ ? log_->messages() : std::vector<std::string>{};
}

}  // namespace ts::gpu
