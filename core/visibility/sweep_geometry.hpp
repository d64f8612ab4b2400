#pragma once
// The geometry of the exact sweep's lines, shared by the scalar sweep (exact_horizons.cpp) and
// the lane-parallel one (sweep_lanes.cpp), which must take the same double and float
// operations in the same order to give the same sums.
//
// Line n of azimuth phi: col * sin(phi) + G(row) * cos(phi) = n * h (row_metrics.hpp).
#include <cmath>
#include <cstddef>

#include "core/terrain/height_grid.hpp"
#include "core/visibility/exact_azimuth.hpp"
#include "core/visibility/horizon_set.hpp"
#include "core/visibility/row_metrics.hpp"

namespace ts::visibility::sweep_geometry {

// What a sweep needs to know about the grid and the receivers.
struct SweepSetup {
    const terrain::HeightGrid& grid;
    const RowMetrics& metrics;
    ReceiverWindow win;  // resolved (no -1 sizes)
    double curvature;    // 1 / (2 R_eff) or 0
    int lines_per_texel;
    double delay;  // the far field's DelayedHull delay in metres (the near field)
};

// Lines through texel centres on the grid's edge must not be lost to rounding (in texels).
constexpr double kEdgeSlack = 1e-7;

// A crossing this close to a line sample is that sample (up to rounding); adding it would put
// two points a hair apart whose rounding noise reads as a near-vertical blocker.
constexpr double kMinCrossing = 1e-3;

// The spacing h of the lines n. Column sweeps: at most 1/lpt rows apart at fixed col (closer
// where rho is larger). Row sweeps: 1/lpt columns apart.
inline double column_line_spacing(const RowMetrics& metrics, int lines_per_texel, double cs) {
    return metrics.min_rho() * std::abs(cs) / lines_per_texel;
}
inline double row_line_spacing(int lines_per_texel, double sn) {
    return std::abs(sn) / lines_per_texel;
}

}  // namespace ts::visibility::sweep_geometry
