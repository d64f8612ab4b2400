#include "core/render/hillshade.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/geo/azimuth.hpp"
#include "core/util/angles.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::render {
using geo::azimuth_cw_from_north_to_phi;
using geo::enu_direction;

namespace {
std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}
}  // namespace

void validate(const HillshadeOptions& o) {
    if (!(o.azimuth_deg >= 0.0 && o.azimuth_deg <= 360.0))
        throw QuantityError(Quantity::sun_azimuth, "", "must be in [0, 360] degrees, got " + number(o.azimuth_deg));
    if (!(o.altitude_deg >= 0.0 && o.altitude_deg <= 90.0)) {
        throw QuantityError(Quantity::sun_elevation, "", "must be in [0, 90] degrees, got " + number(o.altitude_deg));
    }
    if (!(o.z_factor > 0.0) || !std::isfinite(o.z_factor)) {
        throw QuantityError(Quantity::z_factor, "", "must be a finite number > 0, got " + number(o.z_factor));
    }
}

namespace {

// gdaldem's -compute_edges window (GDALGeneric3x3Processing): a neighbour outside the grid is
// extrapolated linearly from the two nearest texels inward, 2a - b (a hole if either is one);
// in the first and last rows the columns are clamped instead (the corner's west column is its
// own); then every hole in the window takes the centre's height. False if the centre is a hole.
bool edge_window(const terrain::HeightGrid& g, int r, int c, float win[9]) {
    const int w = g.width, h = g.height;
    auto z = [&](int rr, int cc) { return g.z[std::size_t(rr) * std::size_t(w) + std::size_t(cc)]; };
    auto extrapolate = [](float a, float b) { return 2.0f * a - b; };  // NaN in, NaN out
    const float centre = z(r, c);
    if (std::isnan(centre)) return false;
    if (r == 0 || r == h - 1) {
        const int cols[3] = {std::max(c - 1, 0), c, std::min(c + 1, w - 1)};
        const int inward = r == 0 ? 1 : h - 2;  // the row next to the edge row
        for (int k = 0; k < 3; ++k) {
            const float edge = z(r, cols[k]), next = z(inward, cols[k]);
            const float outside = extrapolate(edge, next);
            // Window rows north to south: the outside row is north of row 0, south of row h-1.
            win[k] = r == 0 ? outside : z(r - 1, cols[k]);
            win[3 + k] = edge;
            win[6 + k] = r == 0 ? z(1, cols[k]) : outside;
        }
    } else {
        for (int k = 0; k < 3; ++k) {
            const int rr = r - 1 + k;
            const float west = c > 0 ? z(rr, c - 1) : extrapolate(z(rr, 0), z(rr, 1));
            const float east = c < w - 1 ? z(rr, c + 1) : extrapolate(z(rr, w - 1), z(rr, w - 2));
            win[3 * k] = west, win[3 * k + 1] = z(rr, c), win[3 * k + 2] = east;
        }
    }
    for (int k = 0; k < 9; ++k)
        if (std::isnan(win[k])) win[k] = centre;
    return true;
}

std::uint8_t shade_window(const float v[9], double kx, double ky, const glm::dvec3& light) {
    const HornGradient g = horn_gradient(v, v + 3, v + 6, kx, ky);
    return shade_value(g.dz_de, g.dz_dn, light.x, light.y, light.z);
}

}  // namespace

std::vector<std::uint8_t> hillshade(const terrain::HeightGrid& grid, const HillshadeOptions& options) {
    validate(options);
    const int w = grid.width, h = grid.height;
    std::vector<std::uint8_t> out(std::size_t(w) * std::size_t(h), kHillshadeNodata);
    if (options.compute_edges ? (w < 2 || h < 2) : (w < 3 || h < 3)) return out;
    const glm::dvec3 light =
        enu_direction(azimuth_cw_from_north_to_phi(options.azimuth_deg), options.altitude_deg * kPi / 180.0);
    const double zf = options.z_factor;
    // With compute_edges: the border texels and every texel whose window holds a hole, through
    // edge_window; the interior loop below takes the rest.
    auto shade_edge = [&](int r, int c, double kx, double ky) {
        float win[9];
        const std::size_t i = std::size_t(r) * std::size_t(w) + std::size_t(c);
        if ((!grid.void_mask.empty() && grid.void_mask[i]) || !edge_window(grid, r, c, win)) return;
        out[i] = shade_window(win, kx, ky, light);
    };
    auto row_factors = [&](int r, double& kx, double& ky) {
        const double dx = grid.dx_m[std::size_t(r)], dy = grid.dy_m[std::size_t(r)];
        if (!(dx > 0.0) || !(dy > 0.0)) return false;  // a pole row: no east-west extent
        kx = zf / (8.0 * dx), ky = zf / (8.0 * dy);
        return true;
    };
    if (options.compute_edges) {
        for (int r : {0, h - 1}) {
            double kx, ky;
            if (!row_factors(r, kx, ky)) continue;
            for (int c = 0; c < w; ++c) shade_edge(r, c, kx, ky);
        }
    }
    if (h < 3) return out;
    ts::parallel_rows(h - 2, options.threads, w, [&](int begin, int end) {
        for (int r = begin + 1; r < end + 1; ++r) {
            double kx, ky;
            if (!row_factors(r, kx, ky)) continue;
            if (options.compute_edges) {
                shade_edge(r, 0, kx, ky);
                shade_edge(r, w - 1, kx, ky);
            }
            const float* north = grid.z.data() + std::size_t(r - 1) * std::size_t(w);
            const float* mid = north + w;
            const float* south = mid + w;
            std::uint8_t* dst = out.data() + std::size_t(r) * std::size_t(w);
            const std::uint8_t* mask = grid.void_mask.empty() ? nullptr : grid.void_mask.data() + std::size_t(r) * std::size_t(w);
            for (int c = 1; c < w - 1; ++c) {
                const float a = north[c - 1], b = north[c], cc = north[c + 1];
                const float d = mid[c - 1], f = mid[c + 1];
                const float g = south[c - 1], hh = south[c], i = south[c + 1];
                // NaN anywhere in the window makes the sum NaN: one test covers all nine.
                const float all = a + b + cc + d + mid[c] + f + g + hh + i;
                if (mask && mask[c]) continue;
                if (std::isnan(all)) {
                    if (options.compute_edges) shade_edge(r, c, kx, ky);
                    continue;
                }
                const float win[9] = {a, b, cc, d, mid[c], f, g, hh, i};
                dst[c] = shade_window(win, kx, ky, light);
            }
        }
    });
    return out;
}

}  // namespace ts::render
