// The single definition of the sky integrals over a receiver's horizons, shared by C++
// (core/visibility/sky_integrals.cpp) and GLSL (gpu/shaders/vis_sky.comp).
// Written in the common subset of C++ and GLSL (core/util/glsl_compat.h). C++: include
// core/visibility/sky_shared.hpp. GLSL: `#define TS_GLSL 1`, then include this file.
//
// For a horizontal receiver whose horizon elevation rises linearly from a to b across an
// azimuth wedge (docs/visibility.md):
//   mean cos^2 over the wedge = 1/2 + (sin 2b - sin 2a) / (4 (b - a)) = 1/2 + cos(a + b) sinc(b - a) / 2
//   mean sin over the wedge   = (cos a - cos b) / (b - a)              = sin((a + b)/2) sinc((b - a)/2)
// The sinc forms have no cancellation when b is close to a, so they hold in float too.
// Only the upper hemisphere counts: where the horizon is below 0 the receiver sees the whole
// hemisphere in that azimuth (cos^2 -> 1, sin -> 0); a wedge crossing 0 is split there.
// The CPU's whole-raster pass (visibility_products.cpp) evaluates the same means without
// branches or libm calls, for vectorised loops; tests/visibility/visibility_products_test.cpp
// holds it to these functions within float rounding.
#ifndef TS_SKY_SHARED_H
#define TS_SKY_SHARED_H

#include "core/util/glsl_compat.h"

// sin(x)/x, with its Taylor series near 0 (error below x^4/120 there).
TS_INLINE TS_REAL ts_sinc(TS_REAL x) {
    if (abs(x) < 1e-4) return 1.0 - x * x / 6.0;
    return sin(x) / x;
}

TS_INLINE TS_REAL ts_ramp_mean_cos2(TS_REAL a, TS_REAL b) {
    return 0.5 + 0.5 * cos(a + b) * ts_sinc(b - a);
}

TS_INLINE TS_REAL ts_ramp_mean_sin(TS_REAL a, TS_REAL b) {
    return sin(0.5 * (a + b)) * ts_sinc(0.5 * (b - a));
}

// Mean of cos^2(max(0, sigma)) over a wedge where sigma goes linearly from a to b.
TS_INLINE TS_REAL ts_wedge_mean_cos2(TS_REAL a, TS_REAL b) {
    if (a >= 0.0 && b >= 0.0) return ts_ramp_mean_cos2(a, b);
    if (a <= 0.0 && b <= 0.0) return 1.0;
    TS_REAL t0 = a / (a - b);  // fraction of the wedge before the crossing
    if (a > 0.0) return t0 * ts_ramp_mean_cos2(a, 0.0) + (1.0 - t0);
    return t0 + (1.0 - t0) * ts_ramp_mean_cos2(0.0, b);
}

// Mean of sin(max(0, sigma)) over the same wedge.
TS_INLINE TS_REAL ts_wedge_mean_sin(TS_REAL a, TS_REAL b) {
    if (a >= 0.0 && b >= 0.0) return ts_ramp_mean_sin(a, b);
    if (a <= 0.0 && b <= 0.0) return 0.0;
    TS_REAL t0 = a / (a - b);
    if (a > 0.0) return t0 * ts_ramp_mean_sin(a, 0.0);
    return (1.0 - t0) * ts_ramp_mean_sin(0.0, b);
}

#endif  // TS_SKY_SHARED_H
