#pragma once
// The mesh as voxels: the cells its surface passes through ("surface") and the cells it
// encloses ("interior"), robust on open, self-intersecting polygon soups. Inside/outside comes
// from a flood fill from the grid's border, not from orientation or winding, after closing the
// surface by one cell (cracks and holes up to ~2 cells wide do not let the outside in). A part
// that stays open (a single sheet: a wing skin, a sign) is its surface cells: a one-cell-thick
// solid. Each surface cell keeps the corners of the triangle pieces clipped to it, so a sphere
// that holds those corners holds the surface in that cell exactly.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/mesh/triangle_mesh.hpp"

namespace ts::blockers {

enum class VoxelState : std::uint8_t { outside = 0, interior = 1, surface = 2 };

struct VoxelSolid {
    glm::ivec3 dims{0};
    glm::dvec3 origin{0.0};  // corner of cell (0, 0, 0)
    double cell = 1.0;       // edge length, metres
    std::vector<VoxelState> state;

    // Surface cells in CSR form: cell linear index, and the range of their piece corners.
    std::vector<int> surface_cells;
    std::vector<std::uint32_t> corner_begin;  // size surface_cells + 1
    std::vector<glm::dvec3> corners;

    int index(int i, int j, int k) const { return (k * dims.y + j) * dims.x + i; }
    glm::ivec3 coords(int index) const {
        return {index % dims.x, (index / dims.x) % dims.y, index / (dims.x * dims.y)};
    }
    glm::dvec3 cell_center(int index) const { return origin + (glm::dvec3(coords(index)) + 0.5) * cell; }
    // Outside the grid counts as outside.
    bool solid_at(const glm::dvec3& p) const;
    double solid_volume() const;
};

// `resolution` cells along the longest side of the mesh's box (plus a border of 2).
VoxelSolid voxelize_solid(const mesh::TriangleMesh& mesh, int resolution, int threads);

}  // namespace ts::blockers
