#pragma once
// The exact sweep's far field for 8 consecutive lines at once, as the 8 double lanes of
// AVX-512 vectors: lines of one azimuth are independent, and at a given column (row) every
// line of a group takes its sample, its segment's blocker points and its hull query together,
// each lane with its own hull stack and delayed-insertion queue (interleaved, stack[k * 8 +
// lane]) walked by masked vector loops with gathers.
//
// Results are bit-identical to the scalar sweep (exact_horizons.cpp): every lane takes the same
// double/float operations in the same order (this file is compiled without FMA contraction),
// and the splats are added lane by lane in ascending line order, which per texel is the
// scalar sweep's order (it finishes line n before line n + 1, and a texel only receives
// samples taken at its own column / row).
#include "core/visibility/exact_azimuth.hpp"
#include "core/visibility/sweep_geometry.hpp"

namespace ts::visibility {

// Whether this CPU runs the lane sweep (AVX-512 F/VL/DQ).
bool sweep_lanes_supported();

// Sweeps the far field of the lines [n_begin, n_begin + 8k) of `plan` (k as large as fits in
// [n_begin, n_end)) into `sums`, exactly as ExactAzimuthSweep::sweep_far_field's scalar loop
// would, and returns the first line left for the scalar loop (n_begin when the CPU or the grid
// does not suit: grids under 2 x 2 or too large for 32-bit lane indices).
long sweep_lines_simd(const sweep_geometry::SweepSetup& setup, const SweepPlan& plan, long n_begin, long n_end,
                      FarFieldSums& sums);

}  // namespace ts::visibility
