#pragma once
// Which surface cells of a VoxelSolid a sphere holds entirely (every piece corner inside),
// found through blocks of 4x3 cells, and how many spheres hold each cell. The refinement
// keeps every cell's count >= 1: that is the invariant that makes the sphere set bound the
// surface, whatever it moves.
#include <span>
#include <vector>

#include "core/blockers/sphere_blocker.hpp"
#include "core/blockers/voxel_solid.hpp"

namespace ts::blockers {

class SurfaceCover {
public:
    explicit SurfaceCover(const VoxelSolid& solid);

    // Entries (indices into solid.surface_cells) that `s` holds entirely.
    std::vector<int> cells_inside(const Sphere& s) const;
    // The corners of the given entries, one list.
    std::vector<glm::dvec3> corners_of(std::span<const int> entries) const;
    glm::dvec3 cell_center(int entry) const;

    // Counts: add (+1) or remove (-1) a sphere's cells.
    void count(const Sphere& s, int delta);
    int holders(int entry) const { return holders_[std::size_t(entry)]; }
    // Cells the sphere holds that no other sphere does.
    std::vector<int> held_only_by(const Sphere& s) const;

private:
    static constexpr int kBlock = 4;
    const VoxelSolid& solid_;
    glm::ivec3 blocks_{0};
    std::vector<int> block_begin_;  // CSR: entries per block
    std::vector<int> block_items_;
    std::vector<int> holders_;
    bool holds(const Sphere& s, int entry) const;
};

}  // namespace ts::blockers
