#pragma once
// Marching the bilinear surface from a texel centre along a line of constant azimuth, in
// steps of 1/4 texel: the reference method, and the exact method's near field.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/terrain/height_grid.hpp"
#include "core/visibility/row_metrics.hpp"
#include "core/visibility/surface_sampling.hpp"

namespace ts::visibility {

constexpr double kMarchStepTexels = 0.25;

// Largest curvature-corrected slope tan(elevation) = (z - z0)/s - curvature * s seen from
// texel (col, row) at height z0 towards (cos, sin) = (cs, sn) within max_dist metres (to the
// grid's edge if infinite), or -infinity if no surface lies there. Stops early, exactly, once
// even z_top (the grid's highest point) could not beat the best slope found.
//
// band_lo/band_hi (tangents): for callers that only need the answer within a band (the sun's
// disc): the march also stops once the best slope reaches band_hi, or once nothing ahead can
// rise above band_lo; the result is then exact only in being on the same side of the band.
// With the default band the march and its result are unchanged.
inline double march_max_slope(const terrain::HeightGrid& g, const RowMetrics& metrics, double curvature, float z_top,
                              int col, int row, float z0, double cs, double sn,
                              double max_dist = std::numeric_limits<double>::infinity(),
                              double band_lo = -std::numeric_limits<double>::infinity(),
                              double band_hi = std::numeric_limits<double>::infinity()) {
    constexpr double kSlack = 1e-7;  // texels: rays along the grid's edge rows survive sin(pi) != 0
    double best = -std::numeric_limits<double>::infinity();
    double c = col, r = row, s = 0;
    const double wmax = g.width - 1, hmax = g.height - 1;
    for (;;) {
        const double dx = metrics.dx_at(r), dy = metrics.dy_at(r);
        const double ds = kMarchStepTexels * std::min(dx, dy);
        c += cs * ds / dx;
        r -= sn * ds / dy;  // north = towards row 0
        s += ds;
        if (s > max_dist) break;
        if (c < -kSlack || r < -kSlack || c > wmax + kSlack || r > hmax + kSlack) break;
        c = std::clamp(c, 0.0, wmax);
        r = std::clamp(r, 0.0, hmax);
        if ((double(z_top) - z0) / s - curvature * s <= std::max(best, band_lo) || best >= band_hi) break;
        const float z = bilinear_valid(g.z.data(), g.width, g.height, c, r);
        if (std::isnan(z)) continue;
        best = std::max(best, (double(z) - z0) / s - curvature * s);
    }
    return best;
}

// The grid's highest height (voids skipped), for march_max_slope's early exit.
inline float highest_height(const terrain::HeightGrid& g) {
    float m = -std::numeric_limits<float>::infinity();
    for (float v : g.z)
        if (!std::isnan(v)) m = std::max(m, v);
    return m;
}

}  // namespace ts::visibility
