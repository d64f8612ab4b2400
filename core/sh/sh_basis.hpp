#pragma once
// Real orthonormal spherical harmonics of order 4 (l = 0..3, 16 coefficients), index
// i = l*l + l + m, no Condon-Shortley phase; the formulas live in sh_shared.h.
#include <array>
#include <glm/vec3.hpp>

#include "core/util/angles.hpp"

namespace ts::sh {

inline constexpr int kBands = 4;
inline constexpr int kCount = 16;
// The SH coefficient vector of the constant function 1: only the DC term, sqrt(4 pi).
inline constexpr double kSqrt4Pi = 3.5449077018110318;

using ShVec = std::array<double, kCount>;
using ZhVec = std::array<double, kBands>;

constexpr int index(int l, int m) {
    return l * l + l + m;
}
constexpr int band_of(int i) {
    return i < 1 ? 0 : i < 4 ? 1 : i < 9 ? 2 : 3;
}
constexpr int order_of(int i) {
    return i - band_of(i) * band_of(i) - band_of(i);
}

// The 16 basis functions at a unit direction.
ShVec eval(const glm::dvec3& d);
// Each basis function factors as Y_i(d) = H_i(z) trig_m(phi), trig_m = cos(m phi) for m >= 0 and
// sin(|m| phi) for m < 0 (sh_shared.h's ts_sh_eval): H_i(z), Y_i at height z where trig_m = 1.
ShVec eval_height_factors(double z);
// Value of the band-limited function with coefficients f at a unit direction.
double reconstruct(const ShVec& f, const glm::dvec3& d);
// ZH coefficients (axis +z) turned so that the axis points along unit direction d.
ShVec zh_rotate(const ZhVec& zh, const glm::dvec3& d);
// <a, b>: the integral over the sphere of the product of the two band-limited functions.
double dot(const ShVec& a, const ShVec& b);
// L2 norm of the non-DC coefficients (the "magnitude" that drives exponentiation error).
double non_dc_norm(const ShVec& f);

ShVec operator+(const ShVec& a, const ShVec& b);
ShVec operator-(const ShVec& a, const ShVec& b);
ShVec operator*(double s, const ShVec& a);
double norm(const ShVec& a);

}  // namespace ts::sh
