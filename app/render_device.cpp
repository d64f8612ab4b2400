#include "app/render_device.hpp"

#include <cstdio>
#include <exception>
#include <string>

#include "core/sh/exp_method.hpp"
#include "core/util/error.hpp"
#ifdef TERRASHADE_HAS_GPU
#include "gpu/context.hpp"
#include "gpu/render/gpu_render_backend.hpp"
#include "gpu/render/gpu_transfer.hpp"
#endif

namespace ts::app {

#ifdef TERRASHADE_HAS_GPU
struct RenderDevice::Vulkan {
    explicit Vulkan(const gpu::ContextOptions& options)
        : context(options), backend(gpu::render::make_gpu_backend(context)) {}
    gpu::Context context;  // declared first: outlives the backend
    std::unique_ptr<render::RenderBackend> backend;
};
#else
struct RenderDevice::Vulkan {};
#endif

RenderDevice::RenderDevice(const RenderArgs& args) {
#ifdef TERRASHADE_HAS_GPU
    if (args.cpu) return;
    const sh::ExpMethod method = sh::parse_exp_method(args.exp_method);
    if (!gpu::render::runs_on_gpu(method)) {
        if (args.device)
            throw InputError("--device: the GPU runs --exp-method hybrid and scaling_squaring; drop --device or pick "
                             "one");
        std::fprintf(stderr,
                     "terrashade: note: --exp-method %s runs on the CPU (the GPU has hybrid and scaling_squaring)\n",
                     args.exp_method.c_str());
        return;
    }
    try {
        vulkan_ = std::make_unique<Vulkan>(gpu::ContextOptions{.device_index = args.device});
    } catch (const std::exception& e) {
        if (args.device) throw;
        std::fprintf(stderr, "terrashade: warning: no usable Vulkan device, rendering runs on the CPU (%s)\n",
                     e.what());
        return;
    }
    backend_ = vulkan_->backend.get();
#else
    if (args.device) throw InputError("--device: this terrashade was built without Vulkan (TERRASHADE_BUILD_GPU=OFF)");
#endif
}

RenderDevice::~RenderDevice() = default;

}  // namespace ts::app
