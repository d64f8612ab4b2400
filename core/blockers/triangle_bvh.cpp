#include "core/blockers/triangle_bvh.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>

namespace ts::blockers {
namespace {

constexpr int kLeafTriangles = 4;

bool ray_meets_box(const glm::dvec3& o, const glm::dvec3& inv, const glm::dvec3& lo, const glm::dvec3& hi,
                   double t_max) {
    double t0 = 0.0, t1 = t_max;
    for (int k = 0; k < 3; ++k) {
        double a = (lo[k] - o[k]) * inv[k], b = (hi[k] - o[k]) * inv[k];
        if (a > b) std::swap(a, b);
        // NaN (0 * inf on a box face) compares false and leaves the interval as it was.
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        if (t0 > t1) return false;
    }
    return true;
}

}  // namespace

TriangleBvh::TriangleBvh(std::span<const glm::dvec3> positions) {
    const std::size_t n = positions.size() / 3;
    tris_.reserve(n);
    std::vector<glm::dvec3> centroids;
    centroids.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 &a = positions[3 * i], &b = positions[3 * i + 1], &c = positions[3 * i + 2];
        tris_.push_back({a, b - a, c - a});
        centroids.push_back((a + b + c) / 3.0);
    }
    if (n > 0) build(0, int(n), centroids);
}

int TriangleBvh::build(int first, int count, std::vector<glm::dvec3>& centroids) {
    const int index = int(nodes_.size());
    nodes_.push_back({});
    glm::dvec3 lo(1e300), hi(-1e300), clo(1e300), chi(-1e300);
    for (int i = first; i < first + count; ++i) {
        const Tri& t = tris_[std::size_t(i)];
        for (const glm::dvec3& p : {t.a, t.a + t.e1, t.a + t.e2}) lo = glm::min(lo, p), hi = glm::max(hi, p);
        clo = glm::min(clo, centroids[std::size_t(i)]), chi = glm::max(chi, centroids[std::size_t(i)]);
    }
    nodes_[std::size_t(index)].lo = lo, nodes_[std::size_t(index)].hi = hi;
    if (count <= kLeafTriangles) {
        nodes_[std::size_t(index)].first = first, nodes_[std::size_t(index)].count = count;
        return index;
    }
    const glm::dvec3 ext = chi - clo;
    const int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
    // Sort the range's triangles and centroids together by the centroid along the axis.
    std::vector<int> order(static_cast<std::size_t>(count));
    std::iota(order.begin(), order.end(), first);
    const int half = count / 2;
    std::nth_element(order.begin(), order.begin() + half, order.end(), [&](int a, int b) {
        return centroids[std::size_t(a)][axis] < centroids[std::size_t(b)][axis];
    });
    std::vector<Tri> t(static_cast<std::size_t>(count));
    std::vector<glm::dvec3> c(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) t[std::size_t(i)] = tris_[std::size_t(order[std::size_t(i)])],
                                    c[std::size_t(i)] = centroids[std::size_t(order[std::size_t(i)])];
    std::copy(t.begin(), t.end(), tris_.begin() + first);
    std::copy(c.begin(), c.end(), centroids.begin() + first);
    build(first, half, centroids);
    const int right = build(first + half, count - half, centroids);
    nodes_[std::size_t(index)].right = right;
    return index;
}

bool TriangleBvh::occluded(const glm::dvec3& o, const glm::dvec3& d, double t_max) const {
    if (nodes_.empty()) return false;
    const glm::dvec3 inv(1.0 / d.x, 1.0 / d.y, 1.0 / d.z);
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& n = nodes_[std::size_t(stack[--top])];
        if (!ray_meets_box(o, inv, n.lo, n.hi, t_max)) continue;
        if (n.right < 0) {
            for (int i = n.first; i < n.first + n.count; ++i) {
                const Tri& t = tris_[std::size_t(i)];
                const glm::dvec3 p = glm::cross(d, t.e2);
                const double det = glm::dot(t.e1, p);
                if (det == 0.0) continue;  // ray parallel to the triangle's plane
                const double inv_det = 1.0 / det;
                const glm::dvec3 s = o - t.a;
                const double u = glm::dot(s, p) * inv_det;
                if (u < 0.0 || u > 1.0) continue;
                const glm::dvec3 q = glm::cross(s, t.e1);
                const double v = glm::dot(d, q) * inv_det;
                if (v < 0.0 || u + v > 1.0) continue;
                const double tt = glm::dot(t.e2, q) * inv_det;
                if (tt > 0.0 && tt < t_max) return true;
            }
            continue;
        }
        const int left = int(&n - nodes_.data()) + 1;
        stack[top++] = n.right;
        stack[top++] = left;
    }
    return false;
}

}  // namespace ts::blockers
