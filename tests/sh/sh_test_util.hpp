#pragma once
// Helpers shared by the SH tests: an independent evaluation of the real SH basis from the
// associated Legendre recurrence (not the polynomial table in sh_shared.h), random rotations.
#include <cmath>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "core/sh/log_scenes.hpp"
#include "core/sh/sh_basis.hpp"

namespace ts::sh::test {

// P_l^m(x), m >= 0, without the Condon-Shortley phase, by the standard recurrences.
inline double assoc_legendre(int l, int m, double x) {
    double pmm = 1.0;
    const double s = std::sqrt(std::max(0.0, 1.0 - x * x));
    for (int i = 1; i <= m; ++i) pmm *= (2.0 * i - 1.0) * s;
    if (l == m) return pmm;
    double pmm1 = x * (2.0 * m + 1.0) * pmm;
    if (l == m + 1) return pmm1;
    double pll = 0.0;
    for (int ll = m + 2; ll <= l; ++ll) {
        pll = ((2.0 * ll - 1.0) * x * pmm1 - (ll + m - 1.0) * pmm) / (ll - m);
        pmm = pmm1;
        pmm1 = pll;
    }
    return pll;
}

inline double factorial(int n) {
    return n <= 1 ? 1.0 : n * factorial(n - 1);
}

inline double sh_reference(int l, int m, const glm::dvec3& d) {
    const int am = std::abs(m);
    const double k = std::sqrt((2.0 * l + 1.0) / (4.0 * kPi) * factorial(l - am) / factorial(l + am));
    const double phi = std::atan2(d.y, d.x);
    const double p = assoc_legendre(l, am, d.z);
    if (m == 0) return k * p;
    if (m > 0) return std::sqrt(2.0) * k * p * std::cos(m * phi);
    return std::sqrt(2.0) * k * p * std::sin(am * phi);
}

inline glm::dvec3 random_direction(SplitMix64& rng) {
    const double z = rng.uniform(-1.0, 1.0);
    const double phi = rng.uniform(0.0, 2.0 * kPi);
    const double r = std::sqrt(1.0 - z * z);
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Rotation by angle about a unit axis (Rodrigues), column-major glm.
inline glm::dmat3 axis_angle(const glm::dvec3& a, double angle) {
    const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
    glm::dmat3 r;
    r[0] = glm::dvec3(t * a.x * a.x + c, t * a.x * a.y + s * a.z, t * a.x * a.z - s * a.y);
    r[1] = glm::dvec3(t * a.x * a.y - s * a.z, t * a.y * a.y + c, t * a.y * a.z + s * a.x);
    r[2] = glm::dvec3(t * a.x * a.z + s * a.y, t * a.y * a.z - s * a.x, t * a.z * a.z + c);
    return r;
}

inline ShVec random_sh(SplitMix64& rng) {
    ShVec f{};
    for (double& x : f) x = rng.uniform(-1.0, 1.0);
    return f;
}

}  // namespace ts::sh::test
