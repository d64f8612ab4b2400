#include "core/tiles/tile_horn.hpp"

#include <algorithm>
#include <cmath>

#include "core/geo/azimuth.hpp"
#include "core/render/horn.hpp"
#include "core/util/angles.hpp"

namespace ts::tiles {
namespace {

// Calls shade(dz_de, dz_dn) for every covered pixel, with the Horn gradients of its 3x3 window.
template <class Shade>
void for_each_gradient(const TileFrame& f, const std::vector<float>& h, double vertical_scale,
                       const std::uint8_t* covered, std::uint8_t* out, Shade&& shade) {
    const int n = f.size, stride = n + 2;
    const double res = pixel_size_m(f.pixel_zoom);
    for (int j = 0; j < n; ++j) {
        const double y = -pixel_centre_m(f.row0 + j, f.pixel_zoom);
        const double z = vertical_scale * std::cosh(y / kEarthRadiusM);
        const double k = z / (8.0 * res);
        const float* north = h.data() + std::size_t(j) * stride;
        const float* mid = north + stride;
        const float* south = mid + stride;
        for (int i = 0; i < n; ++i) {
            const std::size_t o = std::size_t(j) * n + std::size_t(i);
            if (!covered[o]) continue;
            const float* a = north + i;
            const float* d = mid + i;
            const float* g = south + i;
            if (std::isnan(a[0] + a[1] + a[2] + d[0] + d[1] + d[2] + g[0] + g[1] + g[2])) {
                // At the edge of the terrain (a nodata collar beside it): a height outside takes
                // the centre's, as core/render/hillshade.cpp's edges; no height at the centre
                // leaves the value 0 (the caller makes it transparent).
                if (std::isnan(d[1])) {
                    out[o] = 0;
                    continue;
                }
                float v[9] = {a[0], a[1], a[2], d[0], d[1], d[2], g[0], g[1], g[2]};
                for (float& x : v)
                    if (std::isnan(x)) x = d[1];
                const render::HornGradient edge = render::horn_gradient(v, v + 3, v + 6, k, k);
                out[o] = shade(edge.dz_de, edge.dz_dn);
                continue;
            }
            const render::HornGradient grad = render::horn_gradient(a, d, g, k, k);
            out[o] = shade(grad.dz_de, grad.dz_dn);
        }
    }
}

}  // namespace

void horn_hillshade(const TileFrame& f, const std::vector<float>& heights, double vertical_scale,
                    const HornLight& light, const std::uint8_t* covered, std::uint8_t* out) {
    const glm::dvec3 s = geo::enu_direction(geo::azimuth_cw_from_north_to_phi(light.azimuth_deg),
                                            light.altitude_deg * kPi / 180.0);
    for_each_gradient(f, heights, vertical_scale, covered, out,
                      [&](double e, double n) { return render::shade_value(e, n, s.x, s.y, s.z); });
}

MultidirectionalLight::MultidirectionalLight(double altitude_deg) {
    const double alt = altitude_deg * kPi / 180.0;
    sin127 = 127.0 * std::sin(alt), cos127 = 127.0 * std::cos(alt);
    cos225_cos127 = std::cos(225.0 * kPi / 180.0) * cos127;
    flat = 1.0 + 254.0 * std::sin(alt);
}

std::uint8_t multidirectional_value(double dz_de, double dz_dn, const MultidirectionalLight& l) {
    // GDAL's x, y are -dz/dE and dz/dN here (its z-factor folded in).
    const double x = -dz_de, y = dz_dn;
    const double xx = x * x, yy = y * y, xx_plus_yy = xx + yy;
    if (xx_plus_yy == 0.0) return std::uint8_t(l.flat + 0.5);
    const double v225 = std::max(0.0, l.sin127 + (x - y) * l.cos225_cos127);
    const double v270 = std::max(0.0, l.sin127 - x * l.cos127);
    const double v315 = std::max(0.0, l.sin127 + (x + y) * l.cos225_cos127);
    const double v360 = std::max(0.0, l.sin127 - y * l.cos127);
    const double w225 = 0.5 * xx_plus_yy - x * y, w315 = xx_plus_yy - w225;
    const double cang = ((w225 * v225 + xx * v270 + w315 * v315 + yy * v360) / xx_plus_yy) / std::sqrt(1.0 + xx_plus_yy);
    return std::uint8_t(std::min(255.0, 1.0 + cang) + 0.5);
}

void horn_multidirectional(const TileFrame& f, const std::vector<float>& heights, double vertical_scale,
                           const HornLight& light, const std::uint8_t* covered, std::uint8_t* out) {
    const MultidirectionalLight l(light.altitude_deg);
    for_each_gradient(f, heights, vertical_scale, covered, out,
                      [&](double e, double n) { return multidirectional_value(e, n, l); });
}

}  // namespace ts::tiles
