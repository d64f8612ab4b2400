#pragma once
// Visibility on the GPU: exact horizons (the sweep of core/visibility/exact_horizons.cpp, every
// line of an azimuth in parallel), log-SH per texel, svf and sky_visible, with the CPU path's
// result layouts so callers and tests can swap one for the other.
//
//   gpu::Context context;
//   auto r = gpu::visibility::compute(context, grid, {.horizon = {.directions = 32}});
//   // r.horizons, r.log_sh, r.svf, r.sky_visible as the CPU functions return them
//
// Heights and per-row spacing live whole on the device (every line of a sweep crosses the whole
// grid, so blockers are read from anywhere), split by rows into at most 4 storage buffers
// (maxStorageBufferRange: 128 MiB = 33.5 M texels each on lavapipe, so 134 M texels in all).
// Receivers are processed in bands of rows small enough for each stage's buffers;
// a band's result equals the same rows of a whole-window run (tested bit for bit). Each
// azimuth's lines are swept in passes of 128 samples (llvmpipe ends an invocation's loops after
// 65535 iterations in all), and at most 2048 directions are taken.
#include <string>
#include <vector>

#include "core/terrain/height_grid.hpp"
#include "core/util/uninitialised_vector.hpp"
#include "core/visibility/horizon_options.hpp"
#include "core/visibility/horizon_set.hpp"
#include "core/visibility/horizon_sh.hpp"
#include "gpu/context.hpp"

namespace ts::gpu::visibility {

struct Options {
    // directions, curvature, exact_lines_per_texel, exact_near_field_texels, window and
    // progress are honoured; method exact, or pyramid (handed to compute_pyramid, gpu_pyramid.hpp).
    ts::visibility::HorizonOptions horizon;
    float log_eps = ts::visibility::kDefaultVisibilityLogEps;
    bool log_sh = true;  // compute the 16 log-SH coefficients per texel
    bool sky = true;     // compute svf and sky_visible (linear wedges, as the CPU default)
    // Upper bound on the rows of receivers per band (0 = as many as the buffers allow); tests
    // set it small to check that bands join seamlessly.
    int max_band_rows = 0;
    // Upper bound on the bytes of one buffer of heights (0 = the device's maxStorageBufferRange):
    // heights larger than it are split by rows into up to 4 buffers. Tests set it small to check
    // that a split run equals a whole one.
    std::size_t max_height_buffer_bytes = 0;
};

struct StageTime {
    std::string label;
    double ms;  // device time, summed over bands
};

struct Result {
    ts::visibility::HorizonSet horizons;  // as compute_horizons (NaN for void receivers)
    UninitialisedVector<float> log_sh;    // as log_sh_raster: [coefficient][texel]; empty unless asked
    UninitialisedVector<float> svf;       // as svf_raster; empty unless asked
    UninitialisedVector<float> sky_visible;  // as sky_visible_raster; empty unless asked
    std::vector<StageTime> stages;        // upload, horizons, log_sh, sky, download
    double wall_ms = 0;                   // submit to results, all bands
    int bands = 0;
};

// Throws ts::InputError for bad options or a grid too large for the device's buffers.
Result compute(const Context& context, const terrain::HeightGrid& grid, const Options& options);

}  // namespace ts::gpu::visibility
