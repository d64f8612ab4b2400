#pragma once
// The pyramid method on the GPU (core/visibility/pyramid_horizons.cpp): the mean height pyramid
// built level by level on the device (vis_pyramid_level.comp), then one invocation per receiver
// texel and azimuth marching the schedule's samples through it (vis_pyramid_horizons.comp),
// then log-SH, svf and sky_visible as gpu::visibility::compute does them, with the CPU path's
// result layouts. gpu::visibility::compute hands method pyramid here.
//
// Storage: level 0 (the heights) split by rows into at most 4 storage buffers as in
// gpu_visibility.hpp; level 1 in one buffer and levels 2.. packed in another, so a grid whose
// level 1 exceeds maxStorageBufferRange (128 MiB on lavapipe: 134 M level-0 texels) is refused.
// When every level fits one buffer (grids up to ~25 M texels on lavapipe), the march reads a
// packed copy of them all instead: one load per corner (llvmpipe ran the choice of buffers as
// masked loads from each).
// Receivers run in bands of rows (Options::max_band_rows); a band's result equals the same
// rows of a whole-window run, bit for bit.
#include <cstddef>
#include <vector>

#include "core/terrain/height_grid.hpp"
#include "gpu/context.hpp"
#include "gpu/visibility/gpu_visibility.hpp"

namespace ts::gpu::visibility {

// options.horizon.method must be pyramid; directions, curvature, pyramid_schedule, window and
// progress are honoured. Throws ts::InputError for bad options or a grid too large.
Result compute_pyramid(const Context& context, const terrain::HeightGrid& grid, const Options& options);

// The mean pyramid's levels as the device builds them: level i row-major, the sizes of
// terrain::HeightPyramid (down to one texel). For tests; max_height_buffer_bytes as in Options.
std::vector<std::vector<float>> pyramid_levels(const Context& context, const terrain::HeightGrid& grid,
                                               std::size_t max_height_buffer_bytes = 0);

}  // namespace ts::gpu::visibility
