#pragma once
// A uniform grid over a set of spheres' box, each cell listing the spheres that reach into it:
// "is this point inside any sphere" in a handful of tests instead of one per sphere.
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/blockers/sphere_blocker.hpp"

namespace ts::blockers {

class SphereGrid {
public:
    // About `cells_per_axis` cells along the box's longest side.
    explicit SphereGrid(std::span<const Sphere> spheres, int cells_per_axis = 32);

    bool contains(const glm::dvec3& p) const;
    glm::dvec3 lo() const { return lo_; }
    glm::dvec3 hi() const { return hi_; }

private:
    std::vector<Sphere> spheres_;
    glm::dvec3 lo_{0.0}, hi_{0.0};
    double cell_ = 1.0;
    glm::ivec3 dims_{0};
    std::vector<int> begin_;  // CSR over cells
    std::vector<int> items_;
};

}  // namespace ts::blockers
