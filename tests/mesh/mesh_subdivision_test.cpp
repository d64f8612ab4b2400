// Midpoint subdivision: four triangles per level, the same surface (area and box).
#include <gtest/gtest.h>

#include "core/mesh/mesh_hash.hpp"
#include "core/mesh/mesh_subdivision.hpp"
#include "core/mesh/surface_sampling.hpp"

namespace {

ts::mesh::TriangleMesh one_triangle() {
    ts::mesh::TriangleMesh m;
    m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 3, 1}};
    m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    m.material = {0};
    m.materials = {{"m"}};
    return m;
}

TEST(MeshSubdivision, FourTrianglesPerLevelSameArea) {
    const auto m = one_triangle();
    const auto s = ts::mesh::subdivide_midpoint(m, 3);
    EXPECT_EQ(s.triangle_count(), 64u);
    EXPECT_NEAR(ts::mesh::surface_area(s), ts::mesh::surface_area(m), 1e-5);
    EXPECT_NE(ts::mesh::geometry_hash(s), ts::mesh::geometry_hash(m));
    EXPECT_EQ(ts::mesh::geometry_hash(m), ts::mesh::geometry_hash(one_triangle()));
}

TEST(SurfaceSampling, PointsLieOnTheSurface) {
    const auto m = one_triangle();
    for (const auto& p : ts::mesh::sample_surface(m, 1000, 7)) {
        // The plane through the triangle: z = y / 3, and inside the box.
        EXPECT_NEAR(p.z, p.y / 3.0, 1e-9);
        EXPECT_GE(p.x, -1e-12);
        EXPECT_GE(p.y, -1e-12);
    }
}

}  // namespace
