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
    float fc, fr;
    const int c0 = terrain::valid_bilinear_corner(col, w, fc), r0 = terrain::valid_bilinear_corner(row, h, fr);
    const int c1 = w > 1 ? c0 + 1 : c0, r1 = h > 1 ? r0 + 1 : r0;
    return terrain::blend_valid_corners(z[std::size_t(r0) * w + c0], z[std::size_t(r0) * w + c1],
                                        z[std::size_t(r1) * w + c0], z[std::size_t(r1) * w + c1], fc, fr);
}

}  // namespace ts::visibility
