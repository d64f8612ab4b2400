#include "core/sh/sh_rotation.hpp"

#include <gtest/gtest.h>

#include "core/sh/sphere_quadrature.hpp"
#include "sh_test_util.hpp"

namespace ts::sh {
namespace {

TEST(ShRotation, RotatingAndReprojectingAgree) {
    SplitMix64 rng(17);
    const SphereQuadrature q(8, 16);  // band-limited: exact
    for (int t = 0; t < 20; ++t) {
        const glm::dmat3 R = test::axis_angle(test::random_direction(rng), rng.uniform(-kPi, kPi));
        const ShVec f = test::random_sh(rng);
        const ShVec expected = q.project([&](const glm::dvec3& d) { return reconstruct(f, glm::transpose(R) * d); });
        const ShVec got = ShRotation(R).apply(f);
        // The band matrices come from a 7x7 inverse: a few ulps of conditioning.
        for (int i = 0; i < kCount; ++i) EXPECT_NEAR(got[i], expected[i], 1e-10) << t << " " << i;
    }
}

TEST(ShRotation, TurnsAZhLobeLikeTheZhRotation) {
    SplitMix64 rng(19);
    const ZhVec zh{0.8, -0.4, 0.3, 0.2};
    const glm::dmat3 R = test::axis_angle(test::random_direction(rng), 1.1);
    const ShVec got = ShRotation(R).apply(zh_rotate(zh, {0, 0, 1}));
    const ShVec expected = zh_rotate(zh, R * glm::dvec3(0, 0, 1));
    for (int i = 0; i < kCount; ++i) EXPECT_NEAR(got[i], expected[i], 1e-10);
}

TEST(ShRotation, LocalFrameSeesTheWorldNormalAsZ) {
    // A lobe around the world direction n must become a lobe around +z in the local frame.
    const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
    const glm::dvec3 t = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), n));
    const glm::dvec3 b = glm::cross(n, t);
    const glm::dmat3 frame(t, b, n);
    const ZhVec zh{1.0, 0.5, 0.25, 0.1};
    const ShVec local = ShRotation::to_local_frame(frame).apply(zh_rotate(zh, n));
    const ShVec expected = zh_rotate(zh, {0, 0, 1});
    for (int i = 0; i < kCount; ++i) EXPECT_NEAR(local[i], expected[i], 1e-10);
}

TEST(ShRotation, FloatPathMatchesDouble) {
    SplitMix64 rng(23);
    const ShRotation r(test::axis_angle(test::random_direction(rng), 0.7));
    const ShVec f = test::random_sh(rng);
    float in[16], out[16];
    for (int i = 0; i < 16; ++i) in[i] = static_cast<float>(f[i]);
    r.apply(in, out);
    const ShVec g = r.apply(f);
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(out[i], g[i], 1e-5);  // float round-off
}

}  // namespace
}  // namespace ts::sh
