// The voxel solid: a closed box is solid inside; a single sheet is a one-cell-thick solid whose
// piece corners stay in their cells.
#include <gtest/gtest.h>

#include "core/blockers/voxel_solid.hpp"

namespace {

// The 12 triangles of an axis-aligned box, without the faces listed in `skip` (0..5).
ts::mesh::TriangleMesh box(glm::vec3 lo, glm::vec3 hi, int skip = -1) {
    ts::mesh::TriangleMesh m;
    const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z},
                            {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}};
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int f = 0; f < 6; ++f) {
        if (f == skip) continue;
        for (int t : {0, 2}) {
            const int idx[3] = {faces[f][0], faces[f][t == 0 ? 1 : 2], faces[f][t == 0 ? 2 : 3]};
            for (int k : idx) {
                m.positions.push_back(c[k]);
                m.normals.push_back({0, 0, 1});
            }
            m.material.push_back(0);
        }
    }
    m.materials = {{"box"}};
    return m;
}

TEST(VoxelSolid, ClosedBoxIsSolidInside) {
    const auto solid = ts::blockers::voxelize_solid(box({0, 0, 0}, {2, 1, 1}), 32, 2);
    EXPECT_TRUE(solid.solid_at({1, 0.5, 0.5}));
    EXPECT_FALSE(solid.solid_at({3, 0.5, 0.5}));
    // Volume: the box plus about half a cell of surface cells around it.
    EXPECT_NEAR(solid.solid_volume(), 2.0, 0.5);
}

TEST(VoxelSolid, SheetIsItsSurfaceCells) {
    ts::mesh::TriangleMesh sheet;
    sheet.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    sheet.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    sheet.material = {0};
    sheet.materials = {{"s"}};
    const auto solid = ts::blockers::voxelize_solid(sheet, 16, 1);
    EXPECT_GT(solid.surface_cells.size(), 100u);
    EXPECT_FALSE(solid.solid_at({0.2, 0.2, 0.5}));
    EXPECT_TRUE(solid.solid_at({0.2, 0.2, 0.0}));
    // Every piece corner lies inside its own cell.
    for (std::size_t e = 0; e < solid.surface_cells.size(); ++e)
        for (auto c = solid.corner_begin[e]; c < solid.corner_begin[e + 1]; ++c) {
            const glm::dvec3 d = solid.corners[c] - solid.cell_center(solid.surface_cells[e]);
            for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(d[k]), 0.5 * solid.cell * (1 + 1e-9));
        }
}

}  // namespace
