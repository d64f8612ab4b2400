#pragma once
// Classic local hillshade: Horn (1981) gradients on a 3x3 window, lit by a distant light, as
// `gdaldem hillshade` computes it, but with the true ground spacing of each row (so geographic
// DEMs need no -s scale and their east-west spacing shrinks with latitude as it should).
//
//   dz/dE = ((c + 2f + i) - (a + 2d + g)) / (8 dx)     window  a b c   (north row)
//   dz/dN = ((a + 2b + c) - (g + 2h + i)) / (8 dy)             d e f
//                                                              g h i   (south row)
//   n = (-z dz/dE, -z dz/dN, 1) / |.|   (z = z-factor),  s = light direction in ENU
//   value = 1 + round(254 * max(0, n . s))   in 1..255;  0 = nodata
//
// Border pixels have no full 3x3 window and are 0 (nodata), as gdaldem without
// -compute_edges. A pixel is 0 too when any texel of its window is a hole (NaN height) or when
// the source had no data there (void mask), even if the void was filled since.
//
// The baseline the renderer is compared with (bench relight). It needs only the height grid:
// the `hillshade` command and its test use none of the rest of ts_render.
#include <cstdint>
#include <vector>

#include "core/terrain/height_grid.hpp"

namespace ts::render {

struct HillshadeOptions {
    double azimuth_deg = 315.0;   // light direction, degrees clockwise from north
    double altitude_deg = 45.0;   // light elevation above the horizon, degrees, [0, 90]
    double z_factor = 1.0;        // vertical exaggeration, > 0
    int threads = 0;              // 0 = one per core
};

constexpr std::uint8_t kHillshadeNodata = 0;

// Throws ts::InputError naming the offending flag (--azimuth, --altitude, --z-factor).
void validate(const HillshadeOptions& options);

// Row-major width x height bytes.
std::vector<std::uint8_t> hillshade(const terrain::HeightGrid& grid, const HillshadeOptions& options);

// The shading of one window, 1..255 (exposed for tests). dz_de, dz_dn: gradients in m/m
// including the z-factor; light: unit ENU vector towards the light.
std::uint8_t shade_value(double dz_de, double dz_dn, double light_e, double light_n, double light_u);

}  // namespace ts::render
