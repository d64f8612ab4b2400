#include "core/blockers/sphere_grid.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

namespace ts::blockers {

SphereGrid::SphereGrid(std::span<const Sphere> spheres, int cells_per_axis) : spheres_(spheres.begin(), spheres.end()) {
    if (spheres_.empty()) return;
    lo_ = spheres_[0].center - spheres_[0].radius;
    hi_ = spheres_[0].center + spheres_[0].radius;
    for (const Sphere& s : spheres_) {
        lo_ = glm::min(lo_, s.center - s.radius);
        hi_ = glm::max(hi_, s.center + s.radius);
    }
    const glm::dvec3 size = hi_ - lo_;
    cell_ = std::max(std::max({size.x, size.y, size.z}) / std::max(cells_per_axis, 1), 1e-9);
    for (int a = 0; a < 3; ++a) dims_[a] = std::max(1, int(std::ceil(size[a] / cell_)));
    const std::size_t cells = std::size_t(dims_.x) * std::size_t(dims_.y) * std::size_t(dims_.z);
    std::vector<std::vector<int>> lists(cells);
    for (int s = 0; s < int(spheres_.size()); ++s) {
        const Sphere& sp = spheres_[std::size_t(s)];
        glm::ivec3 c0, c1;
        for (int a = 0; a < 3; ++a) {
            c0[a] = std::clamp(int(std::floor((sp.center[a] - sp.radius - lo_[a]) / cell_)), 0, dims_[a] - 1);
            c1[a] = std::clamp(int(std::floor((sp.center[a] + sp.radius - lo_[a]) / cell_)), 0, dims_[a] - 1);
        }
        for (int k = c0.z; k <= c1.z; ++k)
            for (int j = c0.y; j <= c1.y; ++j)
                for (int i = c0.x; i <= c1.x; ++i) {
                    // Keep the sphere only where it reaches the cell (closest point of the box).
                    const glm::dvec3 box_lo = lo_ + glm::dvec3(i, j, k) * cell_;
                    const glm::dvec3 q = glm::clamp(sp.center, box_lo, box_lo + cell_);
                    if (glm::dot(q - sp.center, q - sp.center) <= sp.radius * sp.radius)
                        lists[std::size_t((k * dims_.y + j) * dims_.x + i)].push_back(s);
                }
    }
    begin_.reserve(cells + 1);
    begin_.push_back(0);
    for (const auto& l : lists) {
        items_.insert(items_.end(), l.begin(), l.end());
        begin_.push_back(int(items_.size()));
    }
}

bool SphereGrid::contains(const glm::dvec3& p) const {
    if (spheres_.empty()) return false;
    const glm::dvec3 q = (p - lo_) / cell_;
    const int i = int(std::floor(q.x)), j = int(std::floor(q.y)), k = int(std::floor(q.z));
    if (i < 0 || j < 0 || k < 0 || i >= dims_.x || j >= dims_.y || k >= dims_.z) {
        // On the far faces of the box (rounding): test all spheres rather than miss.
        if (glm::all(glm::greaterThanEqual(p, lo_)) && glm::all(glm::lessThanEqual(p, hi_)))
            for (const Sphere& s : spheres_)
                if (glm::dot(p - s.center, p - s.center) <= s.radius * s.radius) return true;
        return false;
    }
    const int cell = (k * dims_.y + j) * dims_.x + i;
    for (int n = begin_[std::size_t(cell)]; n < begin_[std::size_t(cell) + 1]; ++n) {
        const Sphere& s = spheres_[std::size_t(items_[std::size_t(n)])];
        if (glm::dot(p - s.center, p - s.center) <= s.radius * s.radius) return true;
    }
    return false;
}

}  // namespace ts::blockers
