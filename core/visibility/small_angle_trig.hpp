#pragma once
// sin(x)/x and cos(x) for small angles |x| <= pi/4 as polynomials in x^2, for loops that GCC
// vectorises across texels (a libm call per texel-azimuth was most of the post-horizon time).
//
// Taylor series cut after the x^12 (sin x / x) and x^14 (cos x) terms. On |x| <= pi/4 the
// first omitted terms bound the truncation: (pi/4)^14 / 15! = 2.6e-14 and (pi/4)^16 / 16! =
// 1.0e-15; with double rounding both are within 5e-14 of std::sin(x)/x and std::cos(x)
// (tests/visibility/small_angle_trig_test.cpp). The outputs they feed are float (6e-8 ulp at 1).
// Horizon angles lie in [-pi/2, pi/2], so callers evaluate these at half the angle.

namespace ts::visibility {

// clang-format off
// sin(x) / x from x2 = x * x (1 at x = 0, no division: also the sinc of a wedge). T: double, or
// float where a loop over texels needs float lanes (the same terms, rounded to float).
template <class T>
inline T sin_over_x(T x2) {
    return T(1.0) + x2 * (T(-1.0 / 6) + x2 * (T(1.0 / 120) + x2 * (T(-1.0 / 5040) + x2 * (T(1.0 / 362880) +
           x2 * (T(-1.0 / 39916800) + x2 * T(1.0 / 6227020800.0))))));
}

// cos(x) from x2 = x * x.
template <class T>
inline T cos_from_square(T x2) {
    return T(1.0) + x2 * (T(-1.0 / 2) + x2 * (T(1.0 / 24) + x2 * (T(-1.0 / 720) + x2 * (T(1.0 / 40320) +
           x2 * (T(-1.0 / 3628800) + x2 * (T(1.0 / 479001600.0) + x2 * T(-1.0 / 87178291200.0)))))));
}
// clang-format on

}  // namespace ts::visibility
