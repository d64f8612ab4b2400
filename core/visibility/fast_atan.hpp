#pragma once
// atan for the sweep's inner loop (one per line sample, where libm's atan is a large share of
// the exact method's time). Odd polynomial of degree 11 fitted on [-1, 1], reflected through
// atan(x) = sign(x) pi/2 - atan(1/x) beyond; maximum error 1.7e-6 rad (1e-4 degree, measured
// over [-1000, 1000] in steps of 1e-4), far below the horizon errors in docs/visibility.md.
#include <cmath>

namespace ts::visibility {

inline double fast_atan(double x) {
    const bool big = std::abs(x) > 1.0;
    const double t = big ? 1.0 / x : x;
    const double t2 = t * t;
    const double p =
        t * (0.99997726 +
             t2 * (-0.33262347 + t2 * (0.19354346 + t2 * (-0.11643287 + t2 * (0.05265332 + t2 * -0.01172120)))));
    if (!big) return p;
    return (x > 0 ? 1.5707963267948966 : -1.5707963267948966) - p;
}

}  // namespace ts::visibility
