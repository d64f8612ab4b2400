#pragma once
// Bilinear interpolation that treats voids (NaN) as missing, not as heights: the weights are
// renormalised over the valid corners, and there is no surface (NaN) only where every corner
// with weight is a void. So a void neither blocks nor drags a slope down to some nodata value,
// and the surface next to a void is the nearest valid heights. Used by the horizon searches
// on flat grids (core/visibility/surface_sampling.hpp) and on pyramid levels (TiledRaster).
#include <cmath>
#include <limits>

namespace ts::terrain {

namespace shared {
using std::isnan;
#include "core/terrain/valid_bilinear_shared.h"
}  // namespace shared

// Corners z00 (col c, row r), z10 (c+1, r), z01 (c, r+1), z11 (c+1, r+1); fractions fc, fr in [0, 1].
// The formula is valid_bilinear_shared.h, the text the GPU's pyramid march compiles too.
inline float blend_valid_corners(float z00, float z10, float z01, float z11, float fc, float fr) {
    return shared::ts_blend_valid_corners(z00, z10, z01, z11, fc, fr);
}

// The lower-left corner index and fraction for a coordinate x in [0, n-1] on an axis of n
// texels: the last texel is reached as corner n-2 with fraction 1, so the east/south
// neighbour always exists (n == 1: corner 0, fraction x).
inline int valid_bilinear_corner(double x, int n, float& fraction) {
    int i = int(x);
    if (i >= n - 1) i = n > 1 ? n - 2 : 0;
    fraction = float(x - i);
    return i;
}

}  // namespace ts::terrain
