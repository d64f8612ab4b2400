#pragma once
// The VkInstance: Vulkan 1.1, with the Khronos validation layer and VK_EXT_debug_utils when
// validation is asked for. Failing to create one (no loader manifest, no driver) becomes a
// one-line ts::InputError naming the package to install.
#include <string>
#include <vector>

#include "gpu/vulkan_api.hpp"

#include "core/util/error.hpp"

namespace ts::gpu {

class ValidationLog;

// The message for "Vulkan cannot run here", with what was observed (detail) and the fix.
InputError no_vulkan_device_error(const std::string& detail);

// The variable that switches validation on from outside: TERRASHADE_VALIDATION=1.
bool validation_requested_by_environment();

struct InstanceOptions {
    // Enable VK_LAYER_KHRONOS_validation; every warning or error it reports goes to log.
    bool validation = false;
    // With validation: also the layer's synchronization validation, which reports missing or
    // wrong barriers between commands (slower; the tests want it).
    bool synchronization_validation = true;
    // Must outlive the instance; required when validation is on (the messenger chained to
    // vkCreateInstance reports into it too).
    ValidationLog* log = nullptr;
    // Further instance extensions (a window's surface extensions); ts::InputError if missing.
    std::vector<std::string> extensions;
};

class Instance {
public:
    explicit Instance(const InstanceOptions& options);
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;
    Instance(Instance&& other) noexcept;
    Instance& operator=(Instance&& other) noexcept;

    VkInstance get() const { return instance_; }
    bool validation_enabled() const { return validation_; }

private:
    VkInstance instance_ = VK_NULL_HANDLE;
    bool validation_ = false;
};

}  // namespace ts::gpu
