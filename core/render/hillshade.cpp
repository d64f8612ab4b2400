#include "core/render/hillshade.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/geo/azimuth.hpp"
#include "core/util/angles.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/error.hpp"

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
    if (!std::isfinite(o.azimuth_deg)) throw InputError("--azimuth: must be a finite number of degrees");
    if (!(o.altitude_deg >= 0.0 && o.altitude_deg <= 90.0)) {
        throw InputError("--altitude: must be in [0, 90] degrees, got " + number(o.altitude_deg));
    }
    if (!(o.z_factor > 0.0) || !std::isfinite(o.z_factor)) {
        throw InputError("--z-factor: must be a finite number > 0, got " + number(o.z_factor));
    }
}

std::uint8_t shade_value(double dz_de, double dz_dn, double light_e, double light_n, double light_u) {
    // n . s with n = (-dz/dE, -dz/dN, 1) / sqrt(1 + |grad|^2).
    const double cosine = (light_u - dz_de * light_e - dz_dn * light_n) / std::sqrt(1.0 + dz_de * dz_de + dz_dn * dz_dn);
    if (!(cosine > 0.0)) return 1;
    // gdaldem stores 1 + 254 cos as float and GDAL rounds to nearest when writing bytes.
    return std::uint8_t(std::lround(std::min(255.0, 1.0 + 254.0 * cosine)));
}

std::vector<std::uint8_t> hillshade(const terrain::HeightGrid& grid, const HillshadeOptions& options) {
    validate(options);
    const int w = grid.width, h = grid.height;
    std::vector<std::uint8_t> out(std::size_t(w) * std::size_t(h), kHillshadeNodata);
    if (w < 3 || h < 3) return out;
    const glm::dvec3 light =
        enu_direction(azimuth_cw_from_north_to_phi(options.azimuth_deg), options.altitude_deg * kPi / 180.0);
    const double zf = options.z_factor;
    ts::parallel_rows(h - 2, options.threads, w, [&](int begin, int end) {
        for (int r = begin + 1; r < end + 1; ++r) {
            const double dx = grid.dx_m[std::size_t(r)], dy = grid.dy_m[std::size_t(r)];
            if (!(dx > 0.0) || !(dy > 0.0)) continue;  // a pole row: no east-west extent
            const double kx = zf / (8.0 * dx), ky = zf / (8.0 * dy);
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
                if (std::isnan(all) || (mask && mask[c])) continue;
                const double dz_de = (double(cc) + 2.0 * f + i - (double(a) + 2.0 * d + g)) * kx;
                const double dz_dn = (double(a) + 2.0 * b + cc - (double(g) + 2.0 * hh + i)) * ky;
                dst[c] = shade_value(dz_de, dz_dn, light.x, light.y, light.z);
            }
        }
    });
    return out;
}

}  // namespace ts::render
