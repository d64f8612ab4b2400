#include "core/sh/sh_basis.hpp"

#include <gtest/gtest.h>

#include "core/sh/sphere_quadrature.hpp"
#include "sh_test_util.hpp"

namespace ts::sh {
namespace {

TEST(ShBasis, IndexHelpersRoundTrip) {
    for (int l = 0; l < kBands; ++l)
        for (int m = -l; m <= l; ++m) {
            EXPECT_EQ(band_of(index(l, m)), l);
            EXPECT_EQ(order_of(index(l, m)), m);
        }
}

TEST(ShBasis, MatchesAssociatedLegendreRecurrence) {
    SplitMix64 rng(7);
    for (int t = 0; t < 200; ++t) {
        const glm::dvec3 d = test::random_direction(rng);
        const ShVec y = eval(d);
        for (int l = 0; l < kBands; ++l)
            for (int m = -l; m <= l; ++m)
                // Two double evaluations of the same polynomial: round-off only.
                EXPECT_NEAR(y[index(l, m)], test::sh_reference(l, m, d), 1e-13) << l << "," << m;
    }
}

TEST(ShBasis, OrthonormalUnderExactQuadrature) {
    // 8 x 16 integrates degree-6 products exactly; tolerance is round-off.
    const SphereQuadrature q(8, 16);
    for (int i = 0; i < kCount; ++i)
        for (int j = 0; j < kCount; ++j) {
            const double v = q.integrate([&](const glm::dvec3& d) { return eval(d)[i] * eval(d)[j]; });
            EXPECT_NEAR(v, i == j ? 1.0 : 0.0, 1e-12) << i << "," << j;
        }
}

TEST(ShBasis, ProjectionOfBandLimitedFunctionIsExact) {
    SplitMix64 rng(3);
    const ShVec f = test::random_sh(rng);
    const SphereQuadrature q(6, 12);
    const ShVec g = q.project([&](const glm::dvec3& d) { return reconstruct(f, d); });
    for (int i = 0; i < kCount; ++i) EXPECT_NEAR(g[i], f[i], 1e-12);
}

TEST(ShBasis, ZhRotationMatchesProjectionOfTurnedLobe) {
    SplitMix64 rng(11);
    const SphereQuadrature q(8, 16);  // the turned lobe is still degree 3: exact
    for (int t = 0; t < 10; ++t) {
        const ZhVec zh{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        const glm::dvec3 axis = test::random_direction(rng);
        const ShVec expected = q.project([&](const glm::dvec3& d) {
            const double c = glm::dot(d, axis);
            double v = 0.0;
            for (int l = 0; l < 4; ++l) v += zh[l] * test::sh_reference(l, 0, glm::dvec3(std::sqrt(1 - c * c), 0, c));
            return v;
        });
        const ShVec got = zh_rotate(zh, axis);
        for (int i = 0; i < kCount; ++i) EXPECT_NEAR(got[i], expected[i], 1e-12);
    }
}

TEST(ShBasis, DoubleProductIsTheIntegralOfTheProduct) {
    SplitMix64 rng(5);
    const ShVec a = test::random_sh(rng), b = test::random_sh(rng);
    const SphereQuadrature q(8, 16);
    const double v = q.integrate([&](const glm::dvec3& d) { return reconstruct(a, d) * reconstruct(b, d); });
    EXPECT_NEAR(dot(a, b), v, 1e-12);
}

}  // namespace
}  // namespace ts::sh
