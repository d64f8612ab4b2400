#pragma once
// The project's one pi and its degree <-> radian conversions. The shaders cannot include C++:
// they use TS_PI of core/util/glsl_compat.h, the same value.
//
// radians() and degrees() multiply by the constant factor (one rounding). Code that converts
// as x * kPi / 180 (rounded twice) keeps that form where its results are outputs: the two can
// differ in the last bit.
#include <numbers>

namespace ts {

inline constexpr double kPi = std::numbers::pi;

constexpr double radians(double deg) {
    return deg * (kPi / 180.0);
}

constexpr double degrees(double rad) {
    return rad * (180.0 / kPi);
}

}  // namespace ts
