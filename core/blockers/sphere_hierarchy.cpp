#include "core/blockers/sphere_hierarchy.hpp"

#include <algorithm>
#include <numeric>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace ts::blockers {

Sphere enclosing_sphere(const Sphere& a, const Sphere& b) {
    const glm::dvec3 d = b.center - a.center;
    const double dist = glm::length(d);
    if (dist + b.radius <= a.radius) return a;
    if (dist + a.radius <= b.radius) return b;
    const double r = 0.5 * (dist + a.radius + b.radius);
    const glm::dvec3 c = a.center + d * ((r - a.radius) / dist);
    // Padded: the children must be inside after rounding too.
    return {c, r * (1.0 + 1e-12)};
}

namespace {
int build(std::span<const Sphere> spheres, std::vector<int>& order, int begin, int end, SphereHierarchy& h) {
    const int node = int(h.nodes.size());
    h.nodes.emplace_back();
    if (end - begin == 1) {
        h.nodes[std::size_t(node)].sphere = order[std::size_t(begin)];
        h.nodes[std::size_t(node)].bound = spheres[std::size_t(order[std::size_t(begin)])];
        return node;
    }
    glm::dvec3 lo = spheres[std::size_t(order[std::size_t(begin)])].center, hi = lo;
    for (int i = begin; i < end; ++i) {
        lo = glm::min(lo, spheres[std::size_t(order[std::size_t(i)])].center);
        hi = glm::max(hi, spheres[std::size_t(order[std::size_t(i)])].center);
    }
    const glm::dvec3 size = hi - lo;
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
    const int mid = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                     [&](int a, int b) { return spheres[std::size_t(a)].center[axis] < spheres[std::size_t(b)].center[axis]; });
    const int left = build(spheres, order, begin, mid, h);
    const int right = build(spheres, order, mid, end, h);
    SphereNode& n = h.nodes[std::size_t(node)];
    n.left = left;
    n.right = right;
    n.bound = enclosing_sphere(h.nodes[std::size_t(left)].bound, h.nodes[std::size_t(right)].bound);
    return node;
}
}  // namespace

SphereHierarchy build_sphere_hierarchy(std::span<const Sphere> spheres) {
    SphereHierarchy h;
    if (spheres.empty()) return h;
    std::vector<int> order(spheres.size());
    std::iota(order.begin(), order.end(), 0);
    h.nodes.reserve(2 * spheres.size());
    build(spheres, order, 0, int(spheres.size()), h);
    return h;
}

namespace {
void flatten(const SphereHierarchy& h, int node, std::vector<FlatSphereNode>& out) {
    const SphereNode& n = h.nodes[std::size_t(node)];
    const std::size_t at = out.size();
    out.push_back({n.bound, 0, n.sphere});
    if (!n.is_leaf()) {
        flatten(h, n.left, out);
        flatten(h, n.right, out);
    }
    out[at].skip = int(out.size());
}
}  // namespace

std::vector<FlatSphereNode> flatten_sphere_hierarchy(const SphereHierarchy& hierarchy) {
    std::vector<FlatSphereNode> out;
    out.reserve(hierarchy.nodes.size());
    if (!hierarchy.nodes.empty()) flatten(hierarchy, 0, out);
    return out;
}

}  // namespace ts::blockers
