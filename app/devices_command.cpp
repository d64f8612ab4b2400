// terrashade devices: the Vulkan devices this machine has, which one terrashade uses by
// default, and (with --test) a quick compute check on one of them.
#include <cstdio>
#include <memory>
#include <optional>

#include "app/command.hpp"
#include "core/util/error.hpp"
#include "gpu/context.hpp"
#include "gpu/debug_messenger.hpp"
#include "gpu/instance.hpp"
#include "gpu/physical_device.hpp"
#include "gpu/self_test.hpp"

namespace ts::app {
namespace {

struct DevicesOptions {
    bool self_test = false;
    std::optional<std::uint32_t> device;
};

void list_devices() {
    const bool validation = gpu::validation_requested_by_environment();
    gpu::ValidationLog log;
    const gpu::Instance instance({.validation = validation, .log = &log});
    const gpu::DebugMessenger messenger =
        validation ? gpu::DebugMessenger(instance.get(), log) : gpu::DebugMessenger();
    const auto devices = gpu::enumerate_physical_devices(instance.get());
    if (devices.empty()) throw gpu::no_vulkan_device_error("no Vulkan device found");
    const auto chosen = gpu::default_device_index(devices);

    std::printf("%-6s %-10s %-9s %s\n", "index", "type", "vulkan", "name");
    for (const auto& device : devices) {
        std::printf("%-6u %-10s %-9s %s", device.index, gpu::device_type_name(device.type),
                    gpu::api_version_string(device.api_version).c_str(), device.name.c_str());
        if (chosen && *chosen == device.index) std::printf("  (default)");
        if (!device.usable()) std::printf("  (unusable: %s)", device.unusable_reason.c_str());
        std::printf("\n");
    }
    if (!chosen) throw gpu::no_vulkan_device_error("no Vulkan device with Vulkan 1.1 and a compute queue");
    std::printf("--device vulkan uses the (default) device; --device auto (every command's default): %s\n",
                gpu::choose_auto_path(devices).reason.c_str());
}

void test_device(const DevicesOptions& options) {
    gpu::ContextOptions context_options;
    context_options.device_index = options.device;
    const gpu::Context context(context_options);
    const auto result = gpu::run_self_test(context);
    const auto& device = context.device_info();
    if (!result.passed) {
        throw std::runtime_error("device " + std::to_string(device.index) + " (" + device.name +
                                 ") failed the compute self-test: " + result.problem);
    }
    std::printf("device %u (%s): compute self-test passed, %u values in %.1f ms%s\n", device.index,
                device.name.c_str(), result.values, result.run_ms,
                context.validation_enabled() ? ", validation on" : "");
}

}  // namespace

void add_devices_command(CLI::App& root) {
    auto options = std::make_shared<DevicesOptions>();
    CLI::App* command = root.add_subcommand(
        "devices", "List the Vulkan devices, which one --device vulkan takes (the first discrete GPU, else integrated, virtual, CPU) and what --device auto picks and why");
    command->add_flag("--test", options->self_test, "Run a small compute kernel on the device and check its result");
    command->add_option("--device", options->device, "With --test: the device index to test (default: the default)");
    command->footer(
        "Set TERRASHADE_VALIDATION=1 to run with the Khronos validation layer (package vulkan-validationlayers).");
    command->callback([options] {
        if (options->device && !options->self_test) throw InputError("--device: only used with --test");
        list_devices();
        if (options->self_test) test_device(*options);
    });
}

}  // namespace ts::app
