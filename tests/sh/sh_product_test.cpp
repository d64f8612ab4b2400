#include "core/sh/sh_product.hpp"

#include <gtest/gtest.h>

#include "core/sh/sphere_quadrature.hpp"
#include "sh_test_util.hpp"

namespace ts::sh {
namespace {

TEST(ShProduct, TriplingTensorMatchesFineQuadrature) {
    const SphereQuadrature q(20, 40);  // independent, finer rule than the one that built it
    std::vector<double> g(kCount * kCount * kCount, 0.0);
    for (std::size_t p = 0; p < q.size(); ++p) {
        const double* y = q.basis(p);
        for (int i = 0; i < kCount; ++i)
            for (int j = 0; j < kCount; ++j)
                for (int k = 0; k < kCount; ++k)
                    g[(i * kCount + j) * kCount + k] += q.weights()[p] * y[i] * y[j] * y[k];
    }
    for (int i = 0; i < kCount; ++i)
        for (int j = 0; j < kCount; ++j)
            for (int k = 0; k < kCount; ++k)
                // Both rules are exact for degree 9: round-off only.
                ASSERT_NEAR(tripling(i, j, k), g[(i * kCount + j) * kCount + k], 1e-12) << i << " " << j << " " << k;
}

TEST(ShProduct, SparseTensorIsSparseAndComplete) {
    const auto& t = tripling_tensor();
    int count = 0;
    for (int i = 0; i < kCount; ++i)
        for (int j = i; j < kCount; ++j)
            for (int k = 0; k < kCount; ++k) count += tripling(i, j, k) != 0.0;
    EXPECT_EQ(static_cast<int>(t.size()), count);
    EXPECT_LT(t.size(), 16u * 17u / 2u * 16u / 3u);  // far sparser than the dense half-tensor
}

TEST(ShProduct, ProductIsProjectionOfPointwiseProduct) {
    SplitMix64 rng(29);
    const SphereQuadrature q(8, 16);  // product of two degree-3 functions times y: degree 9, exact
    for (int t = 0; t < 5; ++t) {
        const ShVec a = test::random_sh(rng), b = test::random_sh(rng);
        const ShVec expected = q.project([&](const glm::dvec3& d) { return reconstruct(a, d) * reconstruct(b, d); });
        const ShVec got = product(a, b);
        for (int i = 0; i < kCount; ++i) EXPECT_NEAR(got[i], expected[i], 1e-12);
        float af[16], bf[16], cf[16], sf[16];
        for (int i = 0; i < 16; ++i) {
            af[i] = static_cast<float>(a[i]);
            bf[i] = static_cast<float>(b[i]);
        }
        product(af, bf, cf);
        for (int i = 0; i < kCount; ++i) EXPECT_NEAR(cf[i], expected[i], 1e-5);  // float round-off
        square(af, sf);
        const ShVec aa = product(a, a);
        for (int i = 0; i < kCount; ++i) EXPECT_NEAR(sf[i], aa[i], 1e-5);
    }
}

TEST(ShProduct, ConstantIsTheIdentity) {
    SplitMix64 rng(31);
    const ShVec a = test::random_sh(rng);
    ShVec one{};
    one[0] = kSqrt4Pi;
    const ShVec p = product(one, a);
    for (int i = 0; i < kCount; ++i) EXPECT_NEAR(p[i], a[i], 1e-13);
}

}  // namespace
}  // namespace ts::sh
