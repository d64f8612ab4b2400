#pragma once
// A binary tree over a sphere set for culling: a leaf holds one sphere; an inner node's sphere
// is the smallest one holding both children's spheres, so it holds every sphere below it (a
// receiver that misses a node's cone misses all of them). Built top down, halving at the
// median of the centres along the longest side of their box.
#include <span>
#include <vector>

#include "core/blockers/sphere_blocker.hpp"

namespace ts::blockers {

struct SphereNode {
    Sphere bound;
    int left = -1, right = -1;  // children (inner nodes), or -1
    int sphere = -1;            // index into the leaf spheres (leaves), or -1
    bool is_leaf() const { return sphere >= 0; }
};

struct SphereHierarchy {
    std::vector<SphereNode> nodes;  // nodes[0] is the root (empty tree: no nodes)
};

// The smallest sphere holding both (one of them, when it holds the other).
Sphere enclosing_sphere(const Sphere& a, const Sphere& b);

SphereHierarchy build_sphere_hierarchy(std::span<const Sphere> spheres);

}  // namespace ts::blockers
