#pragma once
// What the Vulkan visibility kernels can take, shared by the backends that check it.

namespace ts::gpu::visibility {

// log-SH loops ~17 times per direction and llvmpipe ends an invocation's loops after 65535
// iterations in all, so the GPU path takes at most this many azimuths.
inline constexpr int kMaxGpuDirections = 2048;

// The heights are split by rows into at most this many storage buffers (bindings 0..3 of
// vis_surface.glsl's and vis_pyramid_levels.glsl's height_at), each within the device's limit.
inline constexpr int kMaxHeightParts = 4;

}  // namespace ts::gpu::visibility
