#pragma once
// The Vulkan RenderBackend (core/render/render_backend.hpp): the transfer computed once and the
// sky shaded per frame, on a gpu::Context.
//   transfer vectors    gpu::render::TransferField (hybrid or scaling_squaring), T downloaded
//   per-frame shading   T uploaded once and kept on the device; render_shade.comp's dispatches
//                       recorded once (gpu/render/shade_recording.hpp) and re-submitted each
//                       frame with the new light, the radiance read back
// Large grids run in bands (both stages band by the device's storage-buffer range), so the same
// code serves lavapipe and a real GPU.
//
//   gpu::Context context;                                   // must outlive the backend, the
//   auto backend = gpu::render::make_gpu_backend(context);  // renderer and its ShadeFields
//   scene_options.renderer.backend = backend.get();
#include <memory>

#include "core/render/render_backend.hpp"
#include "gpu/context.hpp"

namespace ts::gpu::render {

struct GpuBackendOptions {
    // Upper bound for tests (0 = the device's limits): texels per band of T.
    std::size_t max_band_texels = 0;
};

// Throws ts::InputError when a stage is asked for what the GPU does not run (an exponentiation
// other than hybrid or scaling_squaring).
std::unique_ptr<ts::render::RenderBackend> make_gpu_backend(const Context& context,
                                                            const GpuBackendOptions& options = {});

}  // namespace ts::gpu::render
