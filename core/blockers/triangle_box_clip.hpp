#pragma once
// The part of a triangle inside an axis-aligned box, as a convex polygon (Sutherland-Hodgman
// against the six planes). A sphere holding the polygon's corners holds the whole piece
// (spheres are convex): that is how the decomposition bounds the true surface, not samples.
#include <array>

#include <glm/vec3.hpp>

namespace ts::blockers {

// A triangle clipped by 6 planes has at most 3 + 6 corners.
struct ClippedPolygon {
    std::array<glm::dvec3, 9> corners;
    int size = 0;
};

ClippedPolygon clip_triangle_to_box(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                                    const glm::dvec3& box_lo, const glm::dvec3& box_hi);

}  // namespace ts::blockers
