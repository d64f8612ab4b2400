#include "core/blockers/sun_disc_occlusion.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

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

// The cosine-weighted share of rays that hit the sphere, from a stratified grid over the
// hemisphere (cosine-weighted by construction: r = sqrt(u), phi = 2 pi v on the unit disc).
double sky_cover_by_rays(const Sphere& s, const glm::dvec3& p, const glm::dvec3& n_up) {
    const int k = 800;
    int hits = 0;
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
            const double r = std::sqrt((i + 0.5) / k), phi = 2.0 * kPi * (j + 0.5) / k;
            const glm::dvec3 d(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - r * r)));
            (void)n_up;  // the grid is about +z
            const glm::dvec3 v = s.center - p;
            const double b = glm::dot(v, d), c = glm::dot(v, v) - s.radius * s.radius;
            hits += b > 0 && b * b >= c;
        }
    return double(hits) / (double(k) * k);
}

TEST(SphereSkyCover, AboveIsTheCapsSineSquaredTimesItsCosine) {
    EXPECT_NEAR(sphere_sky_cover({{0, 0, 100}, 10}, {0, 0, 0}, {0, 0, 1}), 0.01, 1e-12);
    const double c = std::cos(radians(40.0));
    const Sphere tilted{{100 * std::sin(radians(40.0)), 0, 100 * c}, 10};
    EXPECT_NEAR(sphere_sky_cover(tilted, {0, 0, 0}, {0, 0, 1}), 0.01 * c, 1e-12);
    EXPECT_EQ(sphere_sky_cover({{0, 0, 100}, 10}, {0, 0, 95}, {0, 0, 1}), 1.0);  // inside
    EXPECT_EQ(sphere_sky_cover({{0, 0, -100}, 10}, {0, 0, 0}, {0, 0, 1}), 0.0);  // below
}

TEST(SphereSkyCover, AStraddlingCapMatchesRaysAndJoinsTheOpenFormula) {
    // Centres from 30 degrees above to 30 degrees below the horizon, 25 m from the receiver,
    // radius 10 m (a 23.6 degree cap): against 640,000 stratified cosine-weighted rays.
    for (double el = -30.0; el <= 30.0; el += 7.5) {
        const Sphere s{{25 * std::cos(radians(el)), 0, 25 * std::sin(radians(el))}, 10};
        const double rays = sky_cover_by_rays(s, {0, 0, 0}, {0, 0, 1});
        EXPECT_NEAR(sphere_sky_cover(s, {0, 0, 0}, {0, 0, 1}), rays, 2e-3) << "elevation " << el;
    }
    // Continuous where the cap's edge touches the plane (the two branches meet).
    const double sigma = std::asin(0.4), el = sigma;
    const Sphere edge{{25 * std::cos(el), 0, 25 * std::sin(el)}, 10};
    const glm::dvec3 up(0, 0, 1);
    const double on = sphere_sky_cover(edge, {0, 0, 0}, up);
    const double above = sphere_sky_cover(edge, {0, 0, -1e-7}, up);
    const double below = sphere_sky_cover(edge, {0, 0, 1e-7}, up);
    EXPECT_NEAR(on, above, 1e-6);
    EXPECT_NEAR(on, below, 1e-6);
}

}  // namespace
}  // namespace ts::blockers
