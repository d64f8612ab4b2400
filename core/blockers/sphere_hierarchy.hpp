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

// The tree in depth-first order for a walk without a stack (the flythrough's shaders): from
// entry i a walk whose test accepts the bound goes on to i + 1 (the first child, or past a
// leaf), and one whose test refuses it jumps to `skip`, just past its subtree.
struct FlatSphereNode {
    Sphere bound;
    int skip = 0;
    int sphere = -1;  // the leaf's sphere, or -1 (inner)
};
std::vector<FlatSphereNode> flatten_sphere_hierarchy(const SphereHierarchy& hierarchy);

}  // namespace ts::blockers

namespace ts::blockers {

// Depth-first walk over the leaves below the nodes `keep(node.bound)` accepts: a node refused
// is skipped with everything below it. Callers pass tests that a sphere inside a refused one
// must fail too (a cone seen from outside a sphere holds the cones of the spheres inside it),
// so the walk finds exactly the leaves the test accepts, without testing them all.
template <class Keep, class Leaf>
void visit_leaves(const SphereHierarchy& h, Keep&& keep, Leaf&& leaf) {
    if (h.nodes.empty()) return;
    int stack[64];  // the tree is balanced: depth <= log2(kMaxSpheres) + 1, far below 64
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const SphereNode& n = h.nodes[std::size_t(stack[--top])];
        if (!keep(n.bound)) continue;
        if (n.is_leaf()) {
            leaf(n.sphere);
            continue;
        }
        stack[top++] = n.right;
        stack[top++] = n.left;
    }
}

}  // namespace ts::blockers
