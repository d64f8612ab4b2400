#pragma once
// The Vulkan VisibilityBackend (core/visibility/visibility_backend.hpp) on a gpu::Context:
// exact and pyramid horizons, log-SH and (linear wedges) svf and sky_visible on the device
// (gpu::visibility::compute); what the device does not run (the raymarch reference, constant
// wedges, more than 2048 directions) is computed on the CPU, and the result's stages say so.
//
//   gpu::Context context;                                          // must outlive the backend
//   auto backend = gpu::visibility::make_gpu_visibility_backend(context);
#include <memory>

#include "core/visibility/visibility_backend.hpp"
#include "gpu/context.hpp"

namespace ts::gpu::visibility {

struct GpuVisibilityOptions {
    int max_band_rows = 0;  // as Options::max_band_rows (tests)
};

std::unique_ptr<ts::visibility::VisibilityBackend> make_gpu_visibility_backend(const Context& context,
                                                                               const GpuVisibilityOptions& options = {});

}  // namespace ts::gpu::visibility
