// The minimal enclosing sphere holds every point and is minimal on cases with a known answer.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "core/blockers/minimal_enclosing_sphere.hpp"
#include "core/blockers/triangle_box_clip.hpp"

namespace {
using ts::blockers::minimal_enclosing_sphere;

TEST(MinimalEnclosingSphere, KnownCases) {
    const std::vector<glm::dvec3> two = {{0, 0, 0}, {2, 0, 0}};
    auto s = minimal_enclosing_sphere(two);
    EXPECT_NEAR(s.radius, 1.0, 1e-8);
    EXPECT_NEAR(s.center.x, 1.0, 1e-12);
    // The cube's corners: the sphere through all eight.
    std::vector<glm::dvec3> cube;
    for (int i = 0; i < 8; ++i) cube.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    s = minimal_enclosing_sphere(cube);
    EXPECT_NEAR(s.radius, std::sqrt(3.0) / 2, 1e-8);
    // Coplanar and collinear sets must not break it.
    const std::vector<glm::dvec3> line = {{0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {2, 0, 0}};
    EXPECT_NEAR(minimal_enclosing_sphere(line).radius, 1.5, 1e-8);
}

TEST(MinimalEnclosingSphere, HoldsRandomPointsAndIsNearlyTight) {
    std::mt19937_64 rng(3);
    std::normal_distribution<double> g;
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<glm::dvec3> pts;
        for (int i = 0; i < 500; ++i) pts.push_back({g(rng), 0.3 * g(rng), trial % 2 ? 0.0 : g(rng)});
        const auto s = minimal_enclosing_sphere(pts);
        double farthest = 0;
        for (const auto& p : pts) {
            EXPECT_LE(glm::length(p - s.center), s.radius);
            farthest = std::max(farthest, glm::length(p - s.center));
        }
        EXPECT_LE(s.radius, farthest * (1 + 1e-8));
        // Minimal: any sphere holding the two farthest-apart points is at least half their distance.
        double diameter = 0;
        for (const auto& a : pts)
            for (const auto& b : pts) diameter = std::max(diameter, glm::length(a - b));
        EXPECT_GE(s.radius, 0.5 * diameter * (1 - 1e-9));
        EXPECT_LE(s.radius, 0.5 * diameter * 1.16);  // Jung's bound: r <= sqrt(3/8) d
    }
}

TEST(TriangleBoxClip, PieceIsInsideTheBoxAndOnTheTriangle) {
    const glm::dvec3 a(-1, 0.5, 0.5), b(2, 0.2, 0.5), c(0.5, 3, 0.5);
    const auto poly = ts::blockers::clip_triangle_to_box(a, b, c, glm::dvec3(0), glm::dvec3(1));
    ASSERT_GE(poly.size, 3);
    for (int i = 0; i < poly.size; ++i) {
        const auto& p = poly.corners[std::size_t(i)];
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(p[k], -1e-12);
            EXPECT_LE(p[k], 1 + 1e-12);
        }
        EXPECT_NEAR(p.z, 0.5, 1e-12);
    }
    const auto none = ts::blockers::clip_triangle_to_box(a, b, c, glm::dvec3(5), glm::dvec3(6));
    EXPECT_EQ(none.size, 0);
}

}  // namespace
