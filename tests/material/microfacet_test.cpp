#include "core/material/microfacet.hpp"
#include "core/util/angles.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/sh/gauss_legendre.hpp"

namespace ts::material {
namespace {


// int D(h) cos(theta_h) dw_h over the hemisphere, by Gauss-Legendre in cos theta_h (D is
// azimuth-independent). 400 nodes resolve m >= 0.05 lobes to ~1e-8.
template <class D>
double projected_area(D&& d) {
    const auto gl = sh::gauss_legendre(400, 0.0, 1.0);
    double s = 0.0;
    for (std::size_t q = 0; q < gl.nodes.size(); ++q) s += gl.weights[q] * 2 * kPi * d(gl.nodes[q]) * gl.nodes[q];
    return s;
}

TEST(Microfacet, DistributionsAreNormalised) {
    for (double m : {0.05, 0.1, 0.3, 0.6, 1.0}) {
        EXPECT_NEAR(projected_area([&](double c) { return beckmann_d(c, m); }), 1.0, 1e-6) << m;
        // GGX has a long tail near grazing; 400 nodes still give 1e-5.
        EXPECT_NEAR(projected_area([&](double c) { return ggx_d(c, m); }), 1.0, 1e-5) << m;
    }
}

TEST(Microfacet, SmithMaskingIsAFractionAndOneAtNormalIncidence) {
    for (double m : {0.1, 0.5, 1.0})
        for (double c = 0.01; c <= 1.0; c += 0.01) {
            for (double g : {smith_g1_beckmann(c, m), smith_g1_ggx(c, m)}) {
                EXPECT_GE(g, 0.0);
                EXPECT_LE(g, 1.0 + 1e-12);
            }
        }
    EXPECT_NEAR(smith_g1_beckmann(1.0, 0.3), 1.0, 1e-12);
    EXPECT_NEAR(smith_g1_ggx(1.0, 0.3), 1.0, 1e-12);
}

TEST(Microfacet, VGrooveIsOneWhenNothingIsMasked) {
    // Normal incidence and viewing: h = n, all cosines 1 -> min(1, 2, 2) = 1.
    EXPECT_EQ(vgroove_g(1.0, 1.0, 1.0, 1.0), 1.0);
    // Grazing view masks: 2 (n.h)(n.o)/(o.h) with n.o small.
    EXPECT_NEAR(vgroove_g(0.9, 0.9, 0.05, 0.5), 2 * 0.9 * 0.05 / 0.5, 1e-15);
}

}  // namespace
}  // namespace ts::material
