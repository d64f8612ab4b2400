#include "core/blockers/surface_cover.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace ts::blockers {

SurfaceCover::SurfaceCover(const VoxelSolid& solid) : solid_(solid), holders_(solid.surface_cells.size(), 0) {
    blocks_ = (solid.dims + (kBlock - 1)) / kBlock;
    const std::size_t nblocks = std::size_t(blocks_.x) * std::size_t(blocks_.y) * std::size_t(blocks_.z);
    std::vector<int> per(nblocks + 1, 0);
    auto block_of = [&](int entry) {
        const glm::ivec3 c = solid.coords(solid.surface_cells[std::size_t(entry)]) / kBlock;
        return (c.z * blocks_.y + c.y) * blocks_.x + c.x;
    };
    const int n = int(solid.surface_cells.size());
    for (int e = 0; e < n; ++e) ++per[std::size_t(block_of(e)) + 1];
    for (std::size_t b = 0; b < nblocks; ++b) per[b + 1] += per[b];
    block_items_.resize(std::size_t(n));
    std::vector<int> fill(per.begin(), per.end() - 1);
    for (int e = 0; e < n; ++e) block_items_[std::size_t(fill[std::size_t(block_of(e))]++)] = e;
    block_begin_ = std::move(per);
}

glm::dvec3 SurfaceCover::cell_center(int entry) const {
    return solid_.cell_center(solid_.surface_cells[std::size_t(entry)]);
}

bool SurfaceCover::holds(const Sphere& s, int entry) const {
    const double half_diagonal = 0.5 * std::sqrt(3.0) * solid_.cell;
    const double d = glm::length(cell_center(entry) - s.center);
    if (d - half_diagonal > s.radius) return false;
    const double r2 = s.radius * s.radius;
    for (std::uint32_t c = solid_.corner_begin[std::size_t(entry)]; c < solid_.corner_begin[std::size_t(entry) + 1]; ++c) {
        const glm::dvec3 v = solid_.corners[c] - s.center;
        if (glm::dot(v, v) > r2) return false;
    }
    return true;
}

std::vector<int> SurfaceCover::cells_inside(const Sphere& s) const {
    std::vector<int> out;
    if (!(s.radius > 0.0)) return out;
    const double span = double(kBlock) * solid_.cell;
    glm::ivec3 b0, b1;
    for (int a = 0; a < 3; ++a) {
        b0[a] = std::clamp(int(std::floor((s.center[a] - s.radius - solid_.origin[a]) / span)), 0, blocks_[a] - 1);
        b1[a] = std::clamp(int(std::floor((s.center[a] + s.radius - solid_.origin[a]) / span)), 0, blocks_[a] - 1);
    }
    for (int k = b0.z; k <= b1.z; ++k)
        for (int j = b0.y; j <= b1.y; ++j)
            for (int i = b0.x; i <= b1.x; ++i) {
                const std::size_t b = std::size_t((k * blocks_.y + j) * blocks_.x + i);
                for (int n = block_begin_[b]; n < block_begin_[b + 1]; ++n)
                    if (holds(s, block_items_[std::size_t(n)])) out.push_back(block_items_[std::size_t(n)]);
            }
    return out;
}

std::vector<glm::dvec3> SurfaceCover::corners_of(std::span<const int> entries) const {
    std::vector<glm::dvec3> out;
    for (int e : entries)
        out.insert(out.end(), solid_.corners.begin() + solid_.corner_begin[std::size_t(e)],
                   solid_.corners.begin() + solid_.corner_begin[std::size_t(e) + 1]);
    return out;
}

void SurfaceCover::count(const Sphere& s, int delta) {
    for (int e : cells_inside(s)) holders_[std::size_t(e)] += delta;
}

std::vector<int> SurfaceCover::held_only_by(const Sphere& s) const {
    std::vector<int> out;
    for (int e : cells_inside(s))
        if (holders_[std::size_t(e)] == 1) out.push_back(e);
    return out;
}

}  // namespace ts::blockers
