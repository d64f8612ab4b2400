#pragma once
// Heights between texel centres, the same surface for every horizon method: bilinear
// interpolation over the valid corners only (terrain::blend_valid_corners), no surface where
// all corners are voids. The pyramid method reads the same surface from its pyramid levels
// (terrain::PyramidLevel::sample_level0_valid).
#include <cmath>
#include <cstddef>
#include <limits>

#include "core/terrain/valid_bilinear.hpp"

namespace ts::visibility {

constexpr float kNoHeight = std::numeric_limits<float>::quiet_NaN();

// Linear interpolation between two heights, either of which may be NaN (a void): the surface
// along a texel row or column, so the same as bilinear_valid there (blend_valid_corners with
// weights 1 - t and t): a valid height with weight only up to rounding (t within 1e-6 of the
// void's own centre) is no surface. Else a sample at a void's centre would take the height
// of the texel beside it on whichever side a rounding of t put it, a whole texel from there.
// A valid height keeps its exact value (no renormalising division).
inline float lerp_valid(float a, float b, float t) {
    const bool va = !std::isnan(a), vb = !std::isnan(b);
    if (va && vb) return a + t * (b - a);
    if (va && 1.0f - t > 1e-6f) return a;
    if (vb && t > 1e-6f) return b;
    return kNoHeight;
}

// Bilinear sample of z (row-major, w x h) at fractional (col, row) inside [0, w-1] x [0, h-1].
inline float bilinear_valid(const float* z, int w, int h, double col, double row) {
    float fc, fr;
    const int c0 = terrain::valid_bilinear_corner(col, w, fc), r0 = terrain::valid_bilinear_corner(row, h, fr);
    const int c1 = w > 1 ? c0 + 1 : c0, r1 = h > 1 ? r0 + 1 : r0;
    return terrain::blend_valid_corners(z[std::size_t(r0) * w + c0], z[std::size_t(r0) * w + c1],
                                        z[std::size_t(r1) * w + c0], z[std::size_t(r1) * w + c1], fc, fr);
}

}  // namespace ts::visibility
