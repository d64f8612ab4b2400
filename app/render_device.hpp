#pragma once
// Where `render`, `relight` and `bench relight` run the renderer's heavy stages (issue 5): the
// Vulkan device by default (gpu/render/gpu_render_backend.hpp: horizons, log-SH, transfer and
// per-frame sky shading), the CPU with --cpu. As `visibility` does: --device N picks a device
// (an error if it cannot be used); without it, a machine with no usable Vulkan device falls back
// to the CPU with a one-line warning. An exponentiation the GPU does not run (--exp-method other
// than hybrid or scaling_squaring) also keeps the CPU, with a note.
//
//   RenderDevice device(args);        // declared before the Scene: it must outlive it
//   device.apply(scene_options);      // sets scene_options.renderer.backend
#include <memory>
#include <string>

#include "app/render_options.hpp"
#include "core/render/render_backend.hpp"
#include "core/render/render_scene.hpp"

namespace ts::app {

class RenderDevice {
public:
    explicit RenderDevice(const RenderArgs& args);
    ~RenderDevice();
    RenderDevice(const RenderDevice&) = delete;
    RenderDevice& operator=(const RenderDevice&) = delete;

    // The backend the renderer gets: nullptr = the CPU path (FrameRenderer's own fused shading).
    render::RenderBackend* backend() const { return backend_; }
    // "cpu" or the Vulkan device's name.
    std::string name() const { return backend_ ? backend_->name() : "cpu"; }
    void apply(render::SceneOptions& options) const { options.renderer.backend = backend_; }

private:
    struct Vulkan;                  // the gpu::Context and its backend (a GPU build only)
    std::unique_ptr<Vulkan> vulkan_;
    render::RenderBackend* backend_ = nullptr;
};

}  // namespace ts::app
