// The spheres' sun shadow on flat ground against its geometry: a sphere of radius r whose
// centre is h above the ground casts an ellipse of semi-axes r (across the sun) and r / sin e
// (along it), centred h / tan e from the point under the sphere, away from the sun.
#include "core/visibility/blocker_sun_shadow.hpp"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/util/angles.hpp"
#include "tests/visibility/synthetic_terrain.hpp"

namespace ts::visibility {
namespace {

blockers::SphereBlockers one_sphere(glm::dvec2 anchor, blockers::Sphere s) {
    blockers::SphereBlockers b;
    blockers::PlacedSpheres p;
    p.anchor = anchor;
    p.spheres = {s};
    p.hierarchy = blockers::build_sphere_hierarchy(p.spheres);
    b.meshes.push_back(p);
    return b;
}

TEST(BlockerSunShadow, FootprintIsTheAnalyticEllipseWhereGeometryPutsIt) {
    const testing::Terrain t = testing::make_terrain(201, 201, 1.0, 1.0, [](double, double) { return 100.0; });
    const double r = 8.0, h = 40.0, az = 135.0, el = 35.0;
    const blockers::SphereBlockers b = one_sphere({100.0, 100.0}, {{0.0, 0.0, 100.0 + h}, r});
    const BlockerSunShadow shadow(t.grid, b, 0.0, 2);
    std::vector<float> vis(t.grid.z.size(), 1.0f);
    shadow.apply(az, el, vis);
    // Shadow centre: h / tan(e) opposite the sun's azimuth (clockwise from north).
    const double shift = h / std::tan(radians(el));
    const glm::dvec2 u(std::sin(radians(az)), std::cos(radians(az)));  // towards the sun, horizontal
    const glm::dvec2 centre = -u * shift;
    long long both = 0, either = 0;
    double sx = 0, sy = 0, n = 0;
    for (int row = 0; row < 201; ++row)
        for (int col = 0; col < 201; ++col) {
            const glm::dvec2 p(col - 100.0, 100.0 - row);
            const glm::dvec2 d = p - centre;
            const double along = glm::dot(d, u), across = u.x * d.y - u.y * d.x;
            const bool analytic = std::pow(along * std::sin(radians(el)) / r, 2) + std::pow(across / r, 2) <= 1.0;
            const bool got = vis[t.grid.index(col, row)] < 0.5f;
            both += analytic && got, either += analytic || got;
            if (got) sx += p.x, sy += p.y, n += 1;
        }
    const double iou = double(both) / double(either);
    std::printf("sun shadow footprint: IoU %.4f with the analytic ellipse, centre (%.2f, %.2f) m, expected (%.2f, %.2f)\n",
                iou, sx / n, sy / n, centre.x, centre.y);
    EXPECT_GE(iou, 0.9);
    EXPECT_NEAR(sx / n, centre.x, 0.5);
    EXPECT_NEAR(sy / n, centre.y, 0.5);
}

TEST(BlockerSunShadow, TouchesOnlyItsFootprintAndClipsAtTheGridEdge) {
    const testing::Terrain t = testing::make_terrain(120, 90, 2.0, 2.0, [](double x, double y) { return 0.01 * x * y; });
    // Anchors inside, on the edge and beyond the grid: no crash, shadows clipped.
    for (const glm::dvec2 anchor : {glm::dvec2(60, 45), glm::dvec2(-1, 45), glm::dvec2(130, -20), glm::dvec2(1e4, 1e4)}) {
        const blockers::SphereBlockers b = one_sphere(anchor, {{0.0, 0.0, 60.0}, 10.0});
        const BlockerSunShadow shadow(t.grid, b, 0.5 / 6.4e6, 2);
        for (const double el : {3.0, 20.0, 70.0}) {
            std::vector<float> vis(t.grid.z.size(), 1.0f);
            shadow.apply(250.0, el, vis);
            const TexelRect rect = shadow.footprint(0, 250.0, el);
            for (int row = 0; row < t.grid.height; ++row)
                for (int col = 0; col < t.grid.width; ++col) {
                    const float v = vis[t.grid.index(col, row)];
                    ASSERT_TRUE(v >= 0.0f && v <= 1.0f);
                    if (!rect.contains(col, row)) {
                        ASSERT_EQ(v, 1.0f);
                    }
                }
        }
    }
}

TEST(BlockerSunShadow, ReceiverInsideOrUnderATouchingSphereIsInShadow) {
    const testing::Terrain t = testing::make_terrain(41, 41, 1.0, 1.0, [](double, double) { return 0.0; });
    const blockers::SphereBlockers touching = one_sphere({20, 20}, {{0.0, 0.0, 5.0}, 5.0});
    std::vector<float> vis(t.grid.z.size(), 1.0f);
    BlockerSunShadow(t.grid, touching, 0.0, 1).apply(0.0, 89.0, vis);
    EXPECT_EQ(vis[t.grid.index(20, 20)], 0.0f);
    const blockers::SphereBlockers sunk = one_sphere({20, 20}, {{0.0, 0.0, 0.0}, 3.0});
    std::fill(vis.begin(), vis.end(), 1.0f);
    BlockerSunShadow(t.grid, sunk, 0.0, 1).apply(0.0, 10.0, vis);
    EXPECT_EQ(vis[t.grid.index(20, 20)], 0.0f);  // inside the sphere
    EXPECT_EQ(vis[t.grid.index(20, 10)], 1.0f);  // 10 m north (row 10), the sun further north
    EXPECT_EQ(vis[t.grid.index(20, 30)], 0.0f);  // 10 m south: the sphere between it and the sun
}

}  // namespace
}  // namespace ts::visibility
