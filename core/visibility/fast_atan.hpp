#pragma once
// atan for the sweep's inner loop (one per line sample, where libm's atan is a large share of
// the exact method's time). Odd polynomial of degree 11 fitted on [-1, 1], reflected through
// atan(x) = sign(x) pi/2 - atan(1/x) beyond; maximum error 1.7e-6 rad (1e-4 degree, measured
// over [-1000, 1000] in steps of 1e-4), far below the horizon errors in docs/visibility.md.
#include <algorithm>
#include <cmath>

namespace ts::visibility {

// The odd polynomial on [-1, 1] both forms below evaluate (and the gather's lanes: T may be a
// vector of lanes, S its element type).
template <class T, class S = T>
inline T atan_unit_interval(T t) {
    const T t2 = t * t;
    return t * (S(0.99997726) +
                t2 * (S(-0.33262347) + t2 * (S(0.19354346) + t2 * (S(-0.11643287) + t2 * (S(0.05265332) + t2 * S(-0.01172120))))));
}

inline double fast_atan(double x) {
    const bool big = std::abs(x) > 1.0;
    const double p = atan_unit_interval(big ? 1.0 / x : x);
    if (!big) return p;
    return (x > 0 ? 1.5707963267948966 : -1.5707963267948966) - p;
}

// The same in float without branches (both reflections computed, then selected), for loops
// over blocks of texels that must vectorise (core/render/horizon_transfer.cpp).
inline float fast_atan_lanes(float x) {
    const float ax = std::abs(x);
    const bool big = ax > 1.0f;
    const float inv = 1.0f / std::max(ax, 1e-30f);
    const float p = atan_unit_interval(big ? inv : ax);
    return std::copysign(big ? 1.5707963f - p : p, x);
}

}  // namespace ts::visibility
