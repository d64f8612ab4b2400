#pragma once
// A bounding volume hierarchy over a triangle soup, for occlusion rays: the reference the
// sphere blockers are measured against (the real triangles' sky and sun shadows,
// docs/blockers.md "Accuracy against the triangles"), and the rays of a mesh's sun shadow
// where its spheres shadow (receiver_blockers.hpp, sun_visible_past_triangles). Axis-aligned
// boxes, split at the median centroid along the longest side, up to 4 triangles a leaf;
// Moller-Trumbore intersection, both faces (meshes are polygon soups, no orientation is
// trusted). Built in core rather than taken from Embree: a few hundred lines' worth, exact
// double arithmetic, and no dependency for a few thousand rays a frame (docs/dependencies.md).
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace ts::blockers {

class TriangleBvh {
public:
    // positions: 3 per triangle.
    explicit TriangleBvh(std::span<const glm::dvec3> positions);

    // Whether the ray origin + t dir, 0 < t < t_max, meets a triangle (dir need not be unit).
    bool occluded(const glm::dvec3& origin, const glm::dvec3& dir, double t_max = 1e300) const;

    // Box of all triangles (empty soup: lo > hi).
    glm::dvec3 lo() const { return nodes_.empty() ? glm::dvec3(1) : nodes_[0].lo; }
    glm::dvec3 hi() const { return nodes_.empty() ? glm::dvec3(0) : nodes_[0].hi; }
    std::size_t triangles() const { return tris_.size(); }

private:
    struct Node {
        glm::dvec3 lo, hi;
        int first = 0, count = 0;  // leaf: triangles [first, first + count)
        int right = -1;            // inner: left child is the next node, right child here
    };
    struct Tri {
        glm::dvec3 a, e1, e2;
    };
    int build(int first, int count, std::vector<glm::dvec3>& centroids);
    std::vector<Node> nodes_;
    std::vector<Tri> tris_;
};

}  // namespace ts::blockers
