#pragma once
// Heights between texel centres, the same surface for every horizon method: bilinear
// interpolation over the valid corners only (weights renormalised), no surface where all
// corners are voids. So a void neither blocks (no height there) nor drags a slope down to
// some nodata value, and the surface next to a void is the nearest valid heights.
#include <cmath>
#include <limits>

#include "core/terrain/height_grid.hpp"

namespace ts::visibility {

constexpr float kNoHeight = std::numeric_limits<float>::quiet_NaN();

// Linear interpolation between two heights, either of which may be NaN (a void).
inline float lerp_valid(float a, float b, float t) {
    const bool va = !std::isnan(a), vb = !std::isnan(b);
    if (va && vb) return a + t * (b - a);
    if (va) return a;
    if (vb) return b;
    return kNoHeight;
}

// Bilinear sample of z (row-major, w x h) at fractional (col, row) inside [0, w-1] x [0, h-1].
inline float bilinear_valid(const float* z, int w, int h, double col, double row) {
    int c0 = int(col), r0 = int(row);
    if (c0 >= w - 1) c0 = w > 1 ? w - 2 : 0;
    if (r0 >= h - 1) r0 = h > 1 ? h - 2 : 0;
    const int c1 = w > 1 ? c0 + 1 : c0, r1 = h > 1 ? r0 + 1 : r0;
    const float fc = float(col - c0), fr = float(row - r0);
    const float z00 = z[std::size_t(r0) * w + c0], z10 = z[std::size_t(r0) * w + c1];
    const float z01 = z[std::size_t(r1) * w + c0], z11 = z[std::size_t(r1) * w + c1];
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
    return wsum > 1e-6f ? sum / wsum : kNoHeight;
}

}  // namespace ts::visibility
