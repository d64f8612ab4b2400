#include "app/compute_device.hpp"

#include <charconv>
#include <cstdio>
#include <exception>
#include <string>

#include "app/options/verbose_option.hpp"
#include "core/util/error.hpp"
#ifdef TERRASHADE_HAS_GPU
#include "gpu/context.hpp"
#include "gpu/instance.hpp"
#include "gpu/physical_device.hpp"
#include "gpu/render/gpu_render_backend.hpp"
#include "gpu/render/gpu_transfer.hpp"
#include "gpu/visibility/gpu_visibility_backend.hpp"
#endif

namespace ts::app {
namespace {

std::optional<std::uint32_t> parse_index(const std::string& text) {
    std::uint32_t v = 0;
    const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || p != text.data() + text.size()) return std::nullopt;
    return v;
}

}  // namespace

void add_device_options(CLI::App& cmd, DeviceArgs& a) {
    auto* device = cmd.add_option("--device", a.device,
                                  "Where to compute: auto (a GPU if there is one, else the CPU path; lavapipe and "
                                  "other CPU implementations of Vulkan count as none), cpu, vulkan, or a Vulkan "
                                  "device index as `terrashade devices` lists it")
                       ->capture_default_str();
    cmd.add_flag("--cpu", a.cpu, "The same as --device cpu")->excludes(device);
    add_verbose_flag(cmd, a.verbose);
}

#ifdef TERRASHADE_HAS_GPU
struct ComputeDevice::Vulkan {
    explicit Vulkan(const gpu::ContextOptions& options)
        : context(options),
          visibility(gpu::visibility::make_gpu_visibility_backend(context)),
          render(gpu::render::make_gpu_backend(context)) {}
    gpu::Context context;  // declared first: outlives the backends
    std::unique_ptr<visibility::VisibilityBackend> visibility;
    std::unique_ptr<render::RenderBackend> render;
};
#else
struct ComputeDevice::Vulkan {};
#endif

// The request is read the same way in every build; only what auto finds, and whether Vulkan can
// be asked for at all, depends on the build.
DeviceChoice choose_device(const DeviceArgs& args) {
    const std::string d = args.cpu ? std::string("cpu") : args.device;
    if (d == "cpu") return {false, std::nullopt, false, "--device cpu"};
    const std::optional<std::uint32_t> index = parse_index(d);
    if (d != "auto" && d != "vulkan" && !index)
        throw InputError("--device " + d + ": give auto, cpu, vulkan or a device index (see terrashade devices)");
#ifdef TERRASHADE_HAS_GPU
    if (index) return {true, index, false, "--device " + d};
    if (d == "vulkan") return {true, std::nullopt, false, "--device vulkan: the best Vulkan device"};
    try {
        const gpu::Instance instance({});
        const auto devices = gpu::enumerate_physical_devices(instance.get());
        const gpu::AutoPath path = gpu::choose_auto_path(devices);
        return {path.device.has_value(), path.device, true, "auto: " + path.reason};
    } catch (const std::exception& e) {
        return {false, std::nullopt, true, std::string("auto: no Vulkan (") + e.what() + "): the CPU path"};
    }
#else
    if (d != "auto")
        throw InputError("--device " + d + ": this terrashade was built without Vulkan (TERRASHADE_BUILD_GPU=OFF)");
    return {false, std::nullopt, true, "auto: this terrashade was built without Vulkan: the CPU path"};
#endif
}

ComputeDevice::ComputeDevice(const DeviceArgs& args) : choice_(choose_device(args)), verbose_(args.verbose) {
#ifdef TERRASHADE_HAS_GPU
    if (choice_.vulkan) {
        try {
            vulkan_ = std::make_unique<Vulkan>(gpu::ContextOptions{.device_index = choice_.index});
            visibility_ = vulkan_->visibility.get();
        } catch (const std::exception& e) {
            if (!choice_.automatic) throw;
            std::fprintf(stderr, "terrashade: warning: the Vulkan device cannot be used, running on the CPU (%s)\n",
                         e.what());
            choice_ = {false, std::nullopt, true, std::string("auto: the Vulkan device failed (") + e.what() + ")"};
        }
    }
#endif
    if (!vulkan_) cpu_visibility_ = visibility::make_cpu_visibility_backend(), visibility_ = cpu_visibility_.get();
    if (verbose_) std::printf("device: %s (%s)\n", name().c_str(), choice_.reason.c_str());
}

ComputeDevice::~ComputeDevice() = default;

std::string ComputeDevice::name() const {
#ifdef TERRASHADE_HAS_GPU
    if (vulkan_) return vulkan_->context.device_info().name + " (Vulkan)";
#endif
    return "cpu";
}

render::RenderBackend* ComputeDevice::render_backend(sh::ExpMethod method) const {
#ifdef TERRASHADE_HAS_GPU
    if (!vulkan_) return nullptr;
    if (!gpu::render::runs_on_gpu(method)) {
        std::fprintf(stderr,
                     "terrashade: note: --exp-method %s runs on the CPU (the GPU has hybrid and scaling_squaring)\n",
                     std::string(sh::to_string(method)).c_str());
        return nullptr;
    }
    return vulkan_->render.get();
#else
    (void)method;
    return nullptr;
#endif
}

void ComputeDevice::apply(render::SceneOptions& options) const {
    options.renderer.visibility = &visibility();
    options.renderer.backend = render_backend(options.renderer.exp_method);
}

}  // namespace ts::app
