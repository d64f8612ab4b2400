#pragma once
// Near the poles a geographic grid's texels are narrow: at 80 degrees a 1-degree texel is 19 km
// east-west and 111 km north-south. Its heights carry no more detail east-west than north-south
// (the data was sampled at the coarser spacing, or averaged there), but gradients taken over the
// narrow spacing turn each column's small differences into steep slopes: shaded, they are
// streaks along the meridians. Each row whose texels are more than twice as tall as wide is
// averaged along the row over as many texels as make one square (a box of 2k + 1 texels,
// k = floor(dy / dx / 2)), so its texels are as wide as they are tall; rows below 2:1 (all of a
// grid within 60 degrees of the equator whose texels are square in degrees, and SRTM's or the
// Copernicus DEM's latitude-dependent spacing) are left as they are.
#include <vector>

#include "core/terrain/height_grid.hpp"

namespace ts::terrain {

// The half-width k of row r's box (0: the row is left as it is).
int isotropic_half_width(const HeightGrid& g, int row);

// Averages the anisotropic rows of `z` (g's heights, row-major) in place. Voids (NaN) stay
// voids and are left out of their neighbours' averages; the ends of a row average over the
// texels there are.
void make_rows_isotropic(const HeightGrid& g, std::vector<float>& z);

}  // namespace ts::terrain
