#include "core/visibility/point_horizons.hpp"

#include <algorithm>
#include <cmath>

#include "core/util/angles.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/horizon_set.hpp"
#include "core/visibility/receiver_setup.hpp"
#include "core/visibility/sun_visibility.hpp"
#include "core/visibility/surface_sampling.hpp"

namespace ts::visibility {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The lowest valid height on the grid's border (the base the terrain continues at beyond it),
// else the lowest anywhere, else 0.
double border_base(const terrain::HeightGrid& g) {
    double lo = kInf;
    auto take = [&](int c, int r) {
        const float z = g.at(c, r);
        if (!std::isnan(z)) lo = std::min(lo, double(z));
    };
    for (int c = 0; c < g.width; ++c) take(c, 0), take(c, g.height - 1);
    for (int r = 0; r < g.height; ++r) take(0, r), take(g.width - 1, r);
    if (lo == kInf)
        for (float z : g.z)
            if (!std::isnan(z)) lo = std::min(lo, double(z));
    return lo == kInf ? 0.0 : lo;
}

}  // namespace

PointHorizons::PointHorizons(const terrain::HeightGrid& grid, const PointHorizonOptions& options)
    : grid_(grid),
      options_(options),
      metrics_(grid),
      curvature_(curvature_factor(options.curvature)),
      base_(border_base(grid)) {
    top_ = -std::numeric_limits<float>::infinity();
    for (float z : grid.z)
        if (!std::isnan(z)) top_ = std::max(top_, z);
    if (!std::isfinite(top_)) top_ = float(base_);
    if (!(options_.step_texels > 0)) options_.step_texels = 0.25;
}

double PointHorizons::plane_max_slope(double z, double a, double b) const {
    if (!options_.base_plane) return -kInf;
    a = std::max(a, 1e-9);
    if (!(b > a)) return -kInf;
    const double dz = base_ - z;  // the plane's height above the point
    auto f = [&](double s) { return dz / s - curvature_ * s; };
    // At or above the point the slope only falls with distance.
    if (dz >= 0) return f(a);
    // Below: -h/s - c s is concave, highest at s* = sqrt(h / c) (at infinity without curvature,
    // where it tends to the horizontal).
    if (curvature_ <= 0) return b == kInf ? 0.0 : f(b);
    return f(std::clamp(std::sqrt(-dz / curvature_), a, b));
}

double PointHorizons::max_slope(glm::dvec2 texel, double z0, double cs, double sn, double band_lo,
                                double band_hi) const {
    const terrain::HeightGrid& g = grid_;
    const double wmax = g.width - 1, hmax = g.height - 1;
    const double row0 = std::clamp(texel.y, 0.0, hmax);
    const double dx0 = metrics_.dx_at(row0), dy0 = metrics_.dy_at(row0);
    const double ds = options_.step_texels * std::min(dx0, dy0);
    // The stretch of the line over the grid, straight in texels with the start's spacing (the
    // march below follows the rows' spacing and stops where it really leaves).
    double s_in = 0, s_out = kInf;
    auto clip = [&](double origin, double u, double hi) {
        if (std::abs(u) < 1e-15) {
            if (origin < 0 || origin > hi) s_out = -1;
            return;
        }
        double ta = (0 - origin) / u, tb = (hi - origin) / u;
        if (ta > tb) std::swap(ta, tb);
        s_in = std::max(s_in, ta), s_out = std::min(s_out, tb);
    };
    clip(texel.x, cs / dx0, wmax);
    clip(texel.y, -sn / dy0, hmax);
    if (!(s_out >= s_in)) return plane_max_slope(z0, 0.0, kInf);

    double best = s_in > 0 ? plane_max_slope(z0, 0.0, s_in) : -kInf;
    // Highest slope anything at distance >= s could have: the grid's top (the base lies below it).
    const double dz_top = double(top_) - z0;
    auto bound = [&](double s) {
        if (dz_top > 0) return dz_top / s - curvature_ * s;
        if (curvature_ <= 0) return 0.0;
        const double se = std::max(s, std::sqrt(-dz_top / curvature_));
        return dz_top / se - curvature_ * se;
    };
    constexpr double kSlack = 1e-7;
    double s = std::max(s_in, ds);
    double c = texel.x + cs / dx0 * s, r = texel.y - sn / dy0 * s;
    const long guard = long(4.0 * (g.width + g.height) / options_.step_texels) + 16;
    for (long k = 0; k < guard; ++k) {
        if (c < -kSlack || r < -kSlack || c > wmax + kSlack || r > hmax + kSlack) {
            if (s > s_in + ds || s_in == 0) break;  // left the grid (or never met it)
        } else {
            if (bound(s) <= std::max(best, band_lo) || best >= band_hi) return best;
            const float z =
                bilinear_valid(g.z.data(), g.width, g.height, std::clamp(c, 0.0, wmax), std::clamp(r, 0.0, hmax));
            if (!std::isnan(z)) best = std::max(best, (double(z) - z0) / s - curvature_ * s);
        }
        const double rr = std::clamp(r, 0.0, hmax);
        c += cs * ds / metrics_.dx_at(rr);
        r -= sn * ds / metrics_.dy_at(rr);  // north = towards row 0
        s += ds;
    }
    return std::max(best, plane_max_slope(z0, s, kInf));
}

void PointHorizons::horizons(glm::dvec2 texel, double z, int directions, float* out) const {
    for (int d = 0; d < directions; ++d) {
        const double phi = azimuth_rad(d, directions);
        out[d] = horizon_angle(max_slope(texel, z, std::cos(phi), std::sin(phi)));
    }
}

double PointHorizons::sun_fraction(glm::dvec2 texel, double z, const glm::dvec3& sun, double sun_radius_rad) const {
    const double e = std::asin(std::clamp(sun.z, -1.0, 1.0));
    const double hl = std::hypot(sun.x, sun.y);
    if (hl < 1e-12) return 1.0;  // straight overhead: no terrain rises to the zenith here
    const double cs = sun.x / hl, sn = sun.y / hl;
    const double lim = 0.5 * kPi - 1e-9;
    const double lo = std::tan(std::clamp(e - sun_radius_rad, -lim, lim));
    const double hi = std::tan(std::clamp(e + sun_radius_rad, -lim, lim));
    const double slope = max_slope(texel, z, cs, sn, lo, hi);
    return sun_disc_visible_fraction(horizon_angle(slope), e, sun_radius_rad);
}

}  // namespace ts::visibility
