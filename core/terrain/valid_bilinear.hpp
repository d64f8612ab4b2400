#pragma once
// Bilinear interpolation that treats voids (NaN) as missing, not as heights: the weights are
// renormalised over the valid corners, and there is no surface (NaN) only where every corner
// with weight is a void. So a void neither blocks nor drags a slope down to some nodata value,
// and the surface next to a void is the nearest valid heights. Used by the horizon searches
// on flat grids (core/visibility/surface_sampling.hpp) and on pyramid levels (TiledRaster).
#include <cmath>
#include <limits>

namespace ts::terrain {

// Corners z00 (col c, row r), z10 (c+1, r), z01 (c, r+1), z11 (c+1, r+1); fractions fc, fr in [0, 1].
inline float blend_valid_corners(float z00, float z10, float z01, float z11, float fc, float fr) {
    if (!std::isnan(z00) && !std::isnan(z10) && !std::isnan(z01) && !std::isnan(z11)) {
        const float top = z00 + fc * (z10 - z00), bottom = z01 + fc * (z11 - z01);
        return top + fr * (bottom - top);
    }
    const float w00 = (1 - fc) * (1 - fr), w10 = fc * (1 - fr), w01 = (1 - fc) * fr, w11 = fc * fr;
    float sum = 0, wsum = 0;
    if (!std::isnan(z00)) sum += w00 * z00, wsum += w00;
    if (!std::isnan(z10)) sum += w10 * z10, wsum += w10;
    if (!std::isnan(z01)) sum += w01 * z01, wsum += w01;
    if (!std::isnan(z11)) sum += w11 * z11, wsum += w11;
    // A point exactly on a valid texel beside voids has weight only there; wsum == 0 means
    // every corner with weight is a void: no surface.
    return wsum > 1e-6f ? sum / wsum : std::numeric_limits<float>::quiet_NaN();
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
