// The single definition of the void-skipping bilinear blend, shared by C++ (terrain::
// blend_valid_corners in valid_bilinear.hpp, used by every horizon method and the CPU
// renderer) and GLSL (gpu/shaders/vis_pyramid_horizons.comp). Written in the common subset of
// C++ and GLSL (core/util/glsl_compat.h), in float in both. GLSL: `#define TS_GLSL 1`, then
// include this file; C++: include valid_bilinear.hpp.
#ifndef TS_VALID_BILINEAR_SHARED_H
#define TS_VALID_BILINEAR_SHARED_H

#include "core/util/glsl_compat.h"

#ifdef TS_GLSL
#define TS_FLOAT_NAN uintBitsToFloat(0x7fc00000u)
#else
#define TS_FLOAT_NAN std::numeric_limits<float>::quiet_NaN()
#endif

// Corners z00 (col c, row r), z10 (c+1, r), z01 (c, r+1), z11 (c+1, r+1); fractions fc, fr in
// [0, 1]. Weights renormalised over the valid (non-NaN) corners; NaN only where every corner
// with weight is a void.
TS_INLINE float ts_blend_valid_corners(float z00, float z10, float z01, float z11, float fc, float fr) {
    if (!isnan(z00) && !isnan(z10) && !isnan(z01) && !isnan(z11)) {
        float top = z00 + fc * (z10 - z00), bottom = z01 + fc * (z11 - z01);
        return top + fr * (bottom - top);
    }
    float one = float(1);
    float w00 = (one - fc) * (one - fr), w10 = fc * (one - fr), w01 = (one - fc) * fr, w11 = fc * fr;
    float sum = float(0), wsum = float(0);
    if (!isnan(z00)) { sum += w00 * z00; wsum += w00; }
    if (!isnan(z10)) { sum += w10 * z10; wsum += w10; }
    if (!isnan(z01)) { sum += w01 * z01; wsum += w01; }
    if (!isnan(z11)) { sum += w11 * z11; wsum += w11; }
    // A point exactly on a valid texel beside voids has weight only there; wsum == 0 means
    // every corner with weight is a void: no surface.
    return wsum > float(1e-6) ? sum / wsum : TS_FLOAT_NAN;
}

#endif  // TS_VALID_BILINEAR_SHARED_H
