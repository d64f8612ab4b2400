#include "core/blockers/sphere_blocker.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/sh/gauss_legendre.hpp"
#include "tests/sh/sh_test_util.hpp"

namespace ts::blockers {
namespace {

using namespace ts::sh;

constexpr double kLogEps = -6.907755278982137;

// Projection of log_eps on the cap of half-angle tb around unit axis a, integrated in the
// cap's own coordinates (Gauss in theta, uniform in phi: exact for the degree-3 integrand).
ShVec cap_quadrature(const glm::dvec3& a, double tb) {
    const glm::dvec3 helper = std::abs(a.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(helper, a));
    const glm::dvec3 v = glm::cross(a, u);
    const GaussLegendre gt = gauss_legendre(24, 0.0, tb);
    const int n_phi = 16;
    ShVec f{};
    for (std::size_t q = 0; q < gt.nodes.size(); ++q)
        for (int j = 0; j < n_phi; ++j) {
            const double t = gt.nodes[q], phi = 2 * kPi * j / n_phi;
            const glm::dvec3 d = std::cos(t) * a + std::sin(t) * (std::cos(phi) * u + std::sin(phi) * v);
            const double w = gt.weights[q] * std::sin(t) * 2 * kPi / n_phi * kLogEps;
            for (int l = 0; l < 4; ++l)
                for (int m = -l; m <= l; ++m) f[index(l, m)] += w * test::sh_reference(l, m, d);
        }
    return f;
}

TEST(SphereBlocker, LogZhMatchesCapQuadrature) {
    for (double tb : {0.01, 0.2, 0.7, 1.2, kPi / 2, 2.5, kPi}) {
        const ZhVec zh = sphere_log_zh(tb, kLogEps);
        const ShVec q = cap_quadrature({0, 0, 1}, tb);
        for (int l = 0; l < 4; ++l) EXPECT_NEAR(zh[l], q[index(l, 0)], 1e-12) << tb << " " << l;
    }
}

TEST(SphereBlocker, RotatedLogShMatchesCapQuadrature) {
    SplitMix64 rng(61);
    for (int t = 0; t < 10; ++t) {
        const glm::dvec3 dir = test::random_direction(rng);
        const double d = rng.uniform(2.0, 10.0), r = rng.uniform(0.1, 1.9);
        const Sphere s{glm::dvec3(1, 2, 3) + d * dir, r};
        const ShVec got = sphere_log_sh(s, {1, 2, 3}, kLogEps);
        const ShVec expected = cap_quadrature(dir, std::asin(r / d));
        for (int i = 0; i < kCount; ++i) EXPECT_NEAR(got[i], expected[i], 1e-11);
    }
}

TEST(SphereBlocker, ReceiverInsideIsFullyOccluded) {
    EXPECT_DOUBLE_EQ(sphere_theta_b(1.0, 0.5), kPi);
    EXPECT_DOUBLE_EQ(sphere_theta_b(1.0, 1.0), kPi);  // on the surface: inside by definition
    EXPECT_DOUBLE_EQ(sphere_theta_b(1.0, 2.0), std::asin(0.5));
    for (double d : {0.0, 0.3, 1.0}) {
        const ShVec f = sphere_log_sh({{0, 0, 0}, 1.0}, {d, 0, 0}, kLogEps);
        EXPECT_NEAR(f[0], kLogEps * kSqrt4Pi, 1e-12);  // log_eps everywhere on the sphere
        for (int i = 1; i < kCount; ++i) EXPECT_NEAR(f[i], 0.0, 1e-12);
    }
}

TEST(SphereBlocker, RatioAttenuationCullsAndCapsTheSolidAngle) {
    const glm::dvec3 x(0, 0, 0), n(0, 0, 1);
    // Below the tangent plane by more than its angular radius: culled. Straddling: kept.
    const std::vector<Sphere> two{{{0, 0, -10}, 1.0}, {{10, 0, -1}, 2.0}};
    const auto w = ratio_attenuation_weights(two, x, n);
    EXPECT_EQ(w[0], 0.0);
    EXPECT_EQ(w[1], 1.0);
    // Many large overlapping blockers above: the weighted solid angle is capped at 2 pi.
    std::vector<Sphere> many;
    for (int b = 0; b < 50; ++b) many.push_back({{0.1 * b, 0, 5}, 3.0});
    const auto wm = ratio_attenuation_weights(many, x, n);
    double total = 0.0;
    for (std::size_t b = 0; b < many.size(); ++b)
        total += wm[b] * cap_solid_angle(sphere_theta_b(3.0, glm::length(many[b].center)));
    EXPECT_NEAR(total, 2 * kPi, 1e-9);
    // Both switched off: plain sum.
    const auto off = ratio_attenuation_weights(many, x, n, {false, false});
    for (double v : off) EXPECT_EQ(v, 1.0);
    // The accumulated vector is the weighted sum.
    const ShVec acc = accumulate_blockers(two, x, n, kLogEps);
    const ShVec one = sphere_log_sh(two[1], x, kLogEps);
    for (int i = 0; i < kCount; ++i) EXPECT_NEAR(acc[i], one[i], 1e-12);
}

}  // namespace
}  // namespace ts::blockers
