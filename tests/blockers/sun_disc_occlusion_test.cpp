#include "core/blockers/sun_disc_occlusion.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/util/angles.hpp"

namespace ts::blockers {
namespace {

TEST(SunDiscOcclusion, OverlapAreaLimits) {
    EXPECT_DOUBLE_EQ(disc_overlap_area(1.0, 2.0, 3.5), 0.0);
    EXPECT_DOUBLE_EQ(disc_overlap_area(1.0, 2.0, 0.5), kPi);
    // Equal discs through each other's centre: 2 pi/3 - sqrt(3)/2 each radius 1.
    EXPECT_NEAR(disc_overlap_area(1.0, 1.0, 1.0), 2.0 * kPi / 3.0 - std::sqrt(3.0) / 2.0, 1e-12);
}

TEST(SunDiscOcclusion, FractionFallsSmoothlyAcrossTheCapEdge) {
    const double a = kSunAngularRadiusRad, cap = 0.3;
    EXPECT_EQ(sun_disc_covered_fraction(a, cap, cap - 1.01 * a), 1.0);
    EXPECT_EQ(sun_disc_covered_fraction(a, cap, cap + 1.01 * a), 0.0);
    // Centre on the edge of a large cap: half the disc, up to the edge's curvature.
    EXPECT_NEAR(sun_disc_covered_fraction(a, cap, cap), 0.5, 0.01);
    double last = 1.0;
    for (int k = -20; k <= 20; ++k) {
        const double f = sun_disc_covered_fraction(a, cap, cap + a * k / 20.0);
        EXPECT_LE(f, last + 1e-12);
        EXPECT_GE(f, 0.0);
        last = f;
    }
}

TEST(SunDiscOcclusion, SphereStraightTowardsTheSunHidesItAndInsideHidesAll) {
    const Sphere s{{0.0, 0.0, 100.0}, 5.0};
    EXPECT_EQ(sphere_sun_cover(s, {0, 0, 0}, {0, 0, 1}), 1.0);
    EXPECT_EQ(sphere_sun_cover(s, {0, 0, 0}, {1, 0, 0}), 0.0);
    EXPECT_EQ(sphere_sun_cover(s, {0, 0, 99}, {1, 0, 0}), 1.0);  // inside
}

}  // namespace
}  // namespace ts::blockers
