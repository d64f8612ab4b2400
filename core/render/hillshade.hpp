#pragma once
// Classic local hillshade: Horn (1981) gradients on a 3x3 window (horn.hpp), lit by a distant light, as
// `gdaldem hillshade` computes it, but with the true ground spacing of each row (so geographic
// DEMs need no -s scale and their east-west spacing shrinks with latitude as it should).
//
//   dz/dE = ((c + 2f + i) - (a + 2d + g)) / (8 dx)     window  a b c   (north row)
//   dz/dN = ((a + 2b + c) - (g + 2h + i)) / (8 dy)             d e f
//                                                              g h i   (south row)
//   n = (-z dz/dE, -z dz/dN, 1) / |.|   (z = z-factor),  s = light direction in ENU
//   value = 1 + round(254 * max(0, n . s))   in 1..255;  0 = nodata
//
// Edges as `gdaldem -compute_edges` (the default, compute_edges): a window cell outside the
// grid is extrapolated linearly from the two texels inward (2a - b; in the first and last rows
// the columns are clamped instead), and a hole (NaN height) in the window takes the centre's
// height, so the border and the rims of holes are shaded too and a 2x2 DEM has four values.
// Without it, as plain gdaldem: border pixels have no full 3x3 window and are 0 (nodata), and
// so is a pixel with any hole in its window. Either way a pixel is 0 when it is a hole or the
// source had no data there (void mask), even if the void was filled since.
//
// The baseline the renderer is compared with (bench relight). It needs only the height grid:
// the `hillshade` command and its test use none of the rest of ts_render.
#include <cstdint>
#include <vector>

#include "core/render/horn.hpp"
#include "core/terrain/height_grid.hpp"

namespace ts::render {

struct HillshadeOptions {
    double azimuth_deg = 315.0;   // light direction, degrees clockwise from north
    double altitude_deg = 45.0;   // light elevation above the horizon, degrees, [0, 90]
    double z_factor = 1.0;        // vertical exaggeration, > 0
    int threads = 0;              // 0 = one per core
    bool compute_edges = true;    // shade the border and holes' rims (gdaldem -compute_edges)
};

constexpr std::uint8_t kHillshadeNodata = 0;

// Throws ts::InputError naming the offending flag (--azimuth, --altitude, --z-factor).
void validate(const HillshadeOptions& options);

// Row-major width x height bytes.
std::vector<std::uint8_t> hillshade(const terrain::HeightGrid& grid, const HillshadeOptions& options);

}  // namespace ts::render
