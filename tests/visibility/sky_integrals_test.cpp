#include "core/util/angles.hpp"
#include "core/visibility/sky_integrals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace ts::visibility;
using ts::kPi;

TEST(SkyIntegrals, FlatHorizonIsWholeSky) {
    const std::vector<float> h(32, 0.0f);
    EXPECT_DOUBLE_EQ(sky_view_factor(h.data(), 32, 1), 1.0);
    EXPECT_DOUBLE_EQ(sky_visible_fraction(h.data(), 32, 1), 1.0);
    // Negative horizons (peaks, curvature) see no more than the upper hemisphere.
    const std::vector<float> low(32, -0.3f);
    EXPECT_DOUBLE_EQ(sky_view_factor(low.data(), 32, 1), 1.0);
    EXPECT_DOUBLE_EQ(sky_visible_fraction(low.data(), 32, 1), 1.0);
}

TEST(SkyIntegrals, ConstantHorizonClosedForm) {
    // A pit with horizon sigma all round: svf = cos^2(sigma), sky_visible = 1 - sin(sigma).
    for (double sigma : {0.1, 0.5, 1.2}) {
        const std::vector<float> h(16, float(sigma));
        // float horizons: 1e-6 covers their rounding.
        EXPECT_NEAR(sky_view_factor(h.data(), 16, 1), std::cos(sigma) * std::cos(sigma), 1e-6);
        EXPECT_NEAR(sky_visible_fraction(h.data(), 16, 1), 1 - std::sin(sigma), 1e-6);
    }
}

TEST(SkyIntegrals, WedgeMeansMatchQuadrature) {
    // Closed forms, including a wedge that crosses 0, against a fine midpoint rule.
    for (auto [a, b] :
         {std::pair{0.2, 0.9}, std::pair{0.7, 0.1}, std::pair{-0.3, 0.5}, std::pair{0.4, -0.6}, std::pair{0.3, 0.3}}) {
        double c2 = 0, s = 0;
        const int n = 100000;
        for (int i = 0; i < n; ++i) {
            const double sig = std::max(0.0, a + (b - a) * (i + 0.5) / n);
            c2 += std::cos(sig) * std::cos(sig) / n;
            s += std::sin(sig) / n;
        }
        // Midpoint rule with 1e5 steps is good to ~1e-9 away from the kink at 0.
        EXPECT_NEAR(wedge_mean_cos2(a, b), c2, 1e-8) << a << " " << b;
        EXPECT_NEAR(wedge_mean_sin(a, b), s, 1e-8) << a << " " << b;
    }
}

TEST(SkyIntegrals, VValleyFloorConvergesWithAzimuths) {
    // Floor of an infinite V valley with walls at slope angle alpha, running north-south:
    // sigma(phi) = atan(tan(alpha) |cos(phi)|), svf = cos(alpha), sky_visible = 1 - 2 alpha / pi.
    const double alpha = 0.6;
    double prev_err = 1;
    for (int d : {8, 16, 32, 64}) {
        std::vector<float> h(static_cast<std::size_t>(d));
        for (int k = 0; k < d; ++k)
            h[std::size_t(k)] = float(std::atan(std::tan(alpha) * std::abs(std::cos(2 * kPi * k / d))));
        const double err = std::abs(sky_view_factor(h.data(), d, 1) - std::cos(alpha));
        EXPECT_LT(err, prev_err) << d;  // interpolating across azimuth converges
        prev_err = err;
        EXPECT_NEAR(sky_visible_fraction(h.data(), d, 1), 1 - 2 * alpha / kPi, 2.0 / (d * d)) << d;
    }
    // At D = 32 the linear wedges are within 1e-3 of the closed form (second-order rule).
    EXPECT_LT(prev_err, 3e-4);
}
