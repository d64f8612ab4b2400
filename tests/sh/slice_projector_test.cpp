#include "core/sh/slice_projector.hpp"
#include "core/util/angles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "core/sh/gauss_legendre.hpp"
#include "core/sh/sh_shared.hpp"
#include "sh_test_util.hpp"

namespace ts::sh {
namespace {

constexpr double kLogEps = -6.907755278982137;

TEST(SliceCoefficients, MatchLegendreQuadrature) {
    for (double deg = -90.0; deg <= 90.0; deg += 7.5) {
        const double sigma = radians(deg);
        double c[4];
        shared::ts_slice_log_coeffs(sigma, kLogEps, c);
        // The integrand is a cubic on [-1, sin sigma]: 4 Gauss nodes are exact.
        const GaussLegendre gl = gauss_legendre(4, -1.0, std::sin(sigma));
        for (int l = 0; l < 4; ++l) {
            double v = 0.0;
            for (int q = 0; q < 4; ++q) v += gl.weights[q] * kLogEps * normalized_legendre(gl.nodes[q])[l];
            EXPECT_NEAR(c[l], v, 1e-13) << deg << " " << l;
        }
    }
}

TEST(SliceCoefficients, ShIntegralsMatchQuadratureInTheta) {
    for (double deg = -90.0; deg <= 90.0; deg += 7.5) {
        const double sigma = radians(deg);
        double e[10];
        shared::ts_slice_sh_integrals(sigma, kLogEps, e);
        // Blocked part theta in [pi/2 - sigma, pi]; smooth integrand in theta, 40 nodes.
        const GaussLegendre gl = gauss_legendre(40, kPi / 2 - sigma, kPi);
        for (int l = 0; l < 4; ++l)
            for (int am = 0; am <= l; ++am) {
                double v = 0.0;
                for (std::size_t q = 0; q < gl.nodes.size(); ++q) {
                    const double t = gl.nodes[q];
                    const glm::dvec3 d(std::sin(t), 0.0, std::cos(t));
                    const double polar = test::sh_reference(l, am, d) / (am == 0 ? 1.0 : std::sqrt(2.0));
                    v += gl.weights[q] * std::sin(t) * kLogEps * polar;
                }
                EXPECT_NEAR(e[l * (l + 1) / 2 + am], v, 1e-12) << deg << " l" << l << " m" << am;
            }
    }
}

// Quadrature of the model: log-visibility blended linearly in azimuth between slices.
// profile(k, theta, phi) is the log-visibility of slice k at (theta, phi) -- for the binary
// model a step, for the Legendre model the 4-term expansion. Wedges are integrated with 16
// Gauss nodes in azimuth (smooth inside a wedge) and 48 in theta per breakpoint interval.
template <class Profile, class Breaks>
ShVec model_quadrature(int slices, Profile&& profile, Breaks&& breaks_of_wedge) {
    ShVec f{};
    const double delta = 2.0 * kPi / slices;
    const GaussLegendre ga = gauss_legendre(16, 0.0, delta);
    for (int k = 0; k < slices; ++k) {
        std::vector<double> edges = breaks_of_wedge(k);
        edges.insert(edges.begin(), 0.0);
        edges.push_back(kPi);
        std::sort(edges.begin(), edges.end());
        for (std::size_t a = 0; a < ga.nodes.size(); ++a) {
            const double u = ga.nodes[a];
            const double tw = u / delta;
            const double phi = SliceProjector::azimuth(k, slices) + u;
            for (std::size_t seg = 0; seg + 1 < edges.size(); ++seg) {
                if (edges[seg + 1] - edges[seg] < 1e-15) continue;
                const GaussLegendre gt = gauss_legendre(48, edges[seg], edges[seg + 1]);
                for (std::size_t q = 0; q < gt.nodes.size(); ++q) {
                    const double t = gt.nodes[q];
                    const double v = (1.0 - tw) * profile(k, t) + tw * profile((k + 1) % slices, t);
                    const glm::dvec3 d(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t));
                    const ShVec y = eval(d);
                    const double w = ga.weights[a] * gt.weights[q] * std::sin(t) * v;
                    for (int i = 0; i < kCount; ++i) f[i] += w * y[i];
                }
            }
        }
    }
    return f;
}

std::vector<float> random_horizons(int slices, SplitMix64& rng) {
    std::vector<float> s(slices);
    for (float& x : s) x = static_cast<float>(radians(rng.uniform(-30.0, 60.0)));
    return s;
}

TEST(SliceProjector, HorizonsMatchQuadratureOfBlendedBinarySlices) {
    SplitMix64 rng(41);
    for (int slices : {4, 7, 32, 128}) {
        const std::vector<float> sigma = random_horizons(slices, rng);
        const SliceProjector p(slices);
        const auto got = p.project_horizons(sigma.data(), static_cast<float>(kLogEps));
        const ShVec expected = model_quadrature(
            slices, [&](int k, double t) { return t >= kPi / 2 - sigma[k] ? kLogEps : 0.0; },
            [&](int k) {
                return std::vector<double>{kPi / 2 - sigma[k], kPi / 2 - sigma[(k + 1) % slices]};
            });
        // float accumulation of D terms of size ~|log eps| * 2pi/D: 1e-4 absolute.
        for (int i = 0; i < kCount; ++i) EXPECT_NEAR(got[i], expected[i], 1e-4) << "D=" << slices << " i=" << i;
    }
}

TEST(SliceProjector, HfAddSliceMatchesProjectHorizons) {
    SplitMix64 rng(43);
    const int slices = 24;
    const std::vector<float> sigma = random_horizons(slices, rng);
    double f[16] = {};
    for (int k = 0; k < slices; ++k)
        shared::ts_hf_add_slice(sigma[k], SliceProjector::azimuth(k, slices), 2 * kPi / slices, kLogEps, f);
    const auto got = SliceProjector(slices).project_horizons(sigma.data(), static_cast<float>(kLogEps));
    for (int i = 0; i < kCount; ++i) EXPECT_NEAR(got[i], f[i], 1e-4);  // float vs double sums
}

TEST(SliceProjector, LegendreCoefficientsMatchQuadratureOfLegendreModel) {
    SplitMix64 rng(47);
    for (int slices : {4, 16, 128}) {
        const std::vector<float> sigma = random_horizons(slices, rng);
        std::vector<float> c(4 * slices);
        std::vector<std::array<double, 4>> cd(slices);
        for (int k = 0; k < slices; ++k) {
            double ck[4];
            shared::ts_slice_log_coeffs(sigma[k], kLogEps, ck);
            for (int l = 0; l < 4; ++l) {
                c[4 * k + l] = static_cast<float>(ck[l]);
                cd[k][l] = ck[l];
            }
        }
        const auto got = SliceProjector(slices).project(c.data());
        const ShVec expected = model_quadrature(
            slices,
            [&](int k, double t) {
                const auto p = normalized_legendre(std::cos(t));
                return cd[k][0] * p[0] + cd[k][1] * p[1] + cd[k][2] * p[2] + cd[k][3] * p[3];
            },
            [](int) { return std::vector<double>{}; });
        for (int i = 0; i < kCount; ++i) EXPECT_NEAR(got[i], expected[i], 1e-4) << "D=" << slices << " i=" << i;
    }
}

TEST(SliceProjector, LegendrePathIsExactForEvenOrdersOnly) {
    SplitMix64 rng(53);
    const int slices = 64;
    const std::vector<float> sigma = random_horizons(slices, rng);
    std::vector<float> c(4 * slices);
    for (int k = 0; k < slices; ++k) {
        double ck[4];
        shared::ts_slice_log_coeffs(sigma[k], kLogEps, ck);
        for (int l = 0; l < 4; ++l) c[4 * k + l] = static_cast<float>(ck[l]);
    }
    const SliceProjector p(slices);
    const auto legendre = p.project(c.data());
    const auto exact = p.project_horizons(sigma.data(), static_cast<float>(kLogEps));
    double worst_odd = 0.0;
    for (int i = 0; i < kCount; ++i) {
        if (std::abs(order_of(i)) % 2 == 0)
            EXPECT_NEAR(legendre[i], exact[i], 1e-4) << i;  // the same integral, float round-off
        else
            worst_odd = std::max(worst_odd, std::abs(double(legendre[i]) - exact[i]));
    }
    std::cout << "[ info ] largest odd-m difference Legendre vs exact path: " << worst_odd << "\n";
}

TEST(SliceProjector, FlatHorizonIsTheLowerHemisphere) {
    const int slices = 8;
    const std::vector<float> sigma(slices, 0.0f);
    const auto got = SliceProjector(slices).project_horizons(sigma.data(), static_cast<float>(kLogEps));
    // The cap of half-angle pi/2 around the nadir (the sphere-cap formula of sh_shared.h).
    double cap[kBands];
    shared::ts_sphere_log_zh(kPi / 2, kLogEps, cap);
    const ShVec expected = zh_rotate({cap[0], cap[1], cap[2], cap[3]}, {0, 0, -1});
    for (int i = 0; i < kCount; ++i) EXPECT_NEAR(got[i], expected[i], 1e-5);
}

TEST(SliceProjector, ExtremeHorizonsBlockAllOrNothing) {
    for (int slices : {4, 128}) {
        const SliceProjector p(slices);
        const std::vector<float> up(slices, static_cast<float>(kPi / 2)), down(slices, static_cast<float>(-kPi / 2));
        const auto all = p.project_horizons(up.data(), static_cast<float>(kLogEps));
        const auto none = p.project_horizons(down.data(), static_cast<float>(kLogEps));
        // float sums of D terms: 1e-5 relative to |log eps| sqrt(4 pi) ~ 24.
        EXPECT_NEAR(all[0], kLogEps * kSqrt4Pi, 1e-4);
        for (int i = 1; i < kCount; ++i) EXPECT_NEAR(all[i], 0.0, 1e-4) << i;
        for (int i = 0; i < kCount; ++i) EXPECT_NEAR(none[i], 0.0, 1e-4) << i;
    }
}

TEST(SliceProjector, RejectsTooFewSlices) {
    EXPECT_THROW(SliceProjector(3), std::invalid_argument);
}

}  // namespace
}  // namespace ts::sh
