#pragma once
// The Horn (1981) hillshade, written once: the gradients of a 3x3 window and the shade of a
// distant light on them. The `hillshade` command (hillshade.hpp, true ground spacing per DEM
// row) and map tiles (core/tiles/tile_horn.hpp, map metres of Web Mercator rows) both call these;
// only how each finds its window and its spacing differs. Inline: a tile spends most of its
// time here, and a call per pixel cost a third of a hillshade tile's time.
//
//   dz/dE = ((c + 2f + i) - (a + 2d + g)) * kx      window  a b c   (north row)
//   dz/dN = ((a + 2b + c) - (g + 2h + i)) * ky              d e f
//                                                           g h i   (south row)
//   kx = z / (8 dx), ky = z / (8 dy)   (z = z-factor or vertical scale, dx, dy in metres)
//   n = (-dz/dE, -dz/dN, 1) / |.|,  s = light direction in ENU
//   value = 1 + round(254 * max(0, n . s))   in 1..255
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ts::render {

struct HornGradient {
    double dz_de, dz_dn;  // m/m, the vertical factor included
};

// north, mid, south: the window's three rows, each from its west column (3 floats).
inline HornGradient horn_gradient(const float* north, const float* mid, const float* south, double kx, double ky) {
    return {(double(north[2]) + 2.0 * mid[2] + south[2] - (double(north[0]) + 2.0 * mid[0] + south[0])) * kx,
            (double(north[0]) + 2.0 * north[1] + north[2] - (double(south[0]) + 2.0 * south[1] + south[2])) * ky};
}

// The shading of one window, 1..255, for a unit ENU vector towards the light.
inline std::uint8_t shade_value(double dz_de, double dz_dn, double light_e, double light_n, double light_u) {
    // n . s with n = (-dz/dE, -dz/dN, 1) / sqrt(1 + |grad|^2).
    const double cosine = (light_u - dz_de * light_e - dz_dn * light_n) / std::sqrt(1.0 + dz_de * dz_de + dz_dn * dz_dn);
    if (!(cosine > 0.0)) return 1;
    // gdaldem stores 1 + 254 cos as float and GDAL rounds to nearest when writing bytes; the
    // value is >= 1, so adding 0.5 and truncating rounds as lround does, without its call.
    return std::uint8_t(std::min(255.0, 1.0 + 254.0 * cosine) + 0.5);
}

}  // namespace ts::render
