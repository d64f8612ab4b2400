// The spheres' sun shadow on flat ground against its geometry: a sphere of radius r whose
// centre is h above the ground casts an ellipse of semi-axes r (across the sun) and r / sin e
// (along it), centred h / tan e from the point under the sphere, away from the sun. A flat
// horizontal plate cast by its triangles: the plate itself, shifted the same way.
#include "core/visibility/blocker_sun_shadow.hpp"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/mesh/placement.hpp"
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

// A wing-like plate, 15 x 6 m in its model frame (x by y), as two triangles.
mesh::TriangleMesh plate_mesh(double half_x, double half_y) {
    mesh::TriangleMesh m;
    const glm::vec3 a(-half_x, -half_y, 0), b(half_x, -half_y, 0), c(half_x, half_y, 0), d(-half_x, half_y, 0);
    m.positions = {a, b, c, a, c, d};
    m.normals.assign(6, glm::vec3(0, 0, 1));
    m.material = {0, 0};
    m.materials.resize(1);
    return m;
}

TEST(BlockerSunShadow, TrianglesCastTheOutlineOfAPlateWhereTheSpheresCastTheirUnion) {
    const testing::Terrain t = testing::make_terrain(241, 241, 1.0, 1.0, [](double, double) { return 100.0; });
    const double half_x = 7.5, half_y = 3.0, h = 40.0, az = 135.0, el = 35.0;
    const mesh::TriangleMesh plate = plate_mesh(half_x, half_y);
    mesh::Placement place;
    place.height_m = 100.0 + h, place.heading_deg = 30.0, place.scale = 2.0;  // 30 x 12 m, turned
    const blockers::Sphere bound{{0, 0, 0}, std::hypot(half_x, half_y)};
    blockers::SphereBlockers by_spheres, by_triangles;
    by_spheres.options.sun_caster = blockers::SphereBlockerOptions::SunCaster::spheres;
    by_spheres.meshes.push_back(blockers::place_spheres({&bound, 1}, place, {120.0, 120.0}, 100.0));
    by_triangles.meshes.push_back(by_spheres.meshes[0]);
    by_triangles.meshes[0].model_triangles = blockers::model_triangle_bvh(plate);
    std::vector<float> vis_s(t.grid.z.size(), 1.0f), vis_t(t.grid.z.size(), 1.0f);
    BlockerSunShadow(t.grid, by_spheres, 0.0, 2).apply(az, el, vis_s);
    BlockerSunShadow(t.grid, by_triangles, 0.0, 2).apply(az, el, vis_t);

    const glm::dvec2 u(std::sin(radians(az)), std::cos(radians(az)));  // towards the sun, horizontal
    const double shift = h / std::tan(radians(el));
    const glm::dmat3 to_model = glm::transpose(mesh::placement_rotation(place)) * (1.0 / place.scale);
    // The disc's rays reach the plate up to (h / sin e) tan(sun radius) = 0.32 m from the central
    // ray's point, across the ray; on the horizontal plate that is up to 1 / sin e longer.
    const double sin_e = std::sin(radians(el));
    const double penumbra = h / sin_e * std::tan(by_triangles.options.sun_radius_rad) / sin_e + 0.02;
    long long both_t = 0, either_t = 0, both_s = 0, either_s = 0;
    // A point is in the plate's shadow when the plate holds it moved up the sun's ray by h;
    // `margin` is its distance (metres on the plate) inside (> 0) or outside the plate's edge.
    for (int row = 0; row < t.grid.height; ++row)
        for (int col = 0; col < t.grid.width; ++col) {
            const glm::dvec2 p = glm::dvec2(col - 120.0, 120.0 - row) + u * shift;
            const glm::dvec3 m = to_model * glm::dvec3(p, 0.0);
            const double margin = place.scale * std::min(half_x - std::abs(m.x), half_y - std::abs(m.y));
            const bool analytic = margin > 0;
            const float vt = vis_t[t.grid.index(col, row)], vs = vis_s[t.grid.index(col, row)];
            if (margin > penumbra) {
                EXPECT_EQ(vt, 0.0f) << col << "," << row << ": " << margin << " m inside";
            }
            if (margin < -penumbra) {
                EXPECT_EQ(vt, 1.0f) << col << "," << row << ": " << -margin << " m outside";
            }
            both_t += analytic && vt < 0.5f, either_t += analytic || vt < 0.5f;
            both_s += analytic && vs < 0.5f, either_s += analytic || vs < 0.5f;
        }
    const double iou_t = double(both_t) / double(either_t), iou_s = double(both_s) / double(either_s);
    std::printf("a 30 x 12 m plate 40 m up, sun 35 deg: shadow IoU with the plate's outline %.4f cast by its triangles, "
                "%.4f by its bounding sphere\n", iou_t, iou_s);
    EXPECT_GE(iou_t, 0.97);
    EXPECT_LT(iou_s, 0.5);  // the ellipse of a sphere holding the plate
}

}  // namespace
}  // namespace ts::visibility
