#pragma once
// Two unit vectors t, b that make (t, b, n) a right-handed orthonormal frame about the unit
// direction n (t horizontal unless n is near the vertical).
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace ts {

inline void unit_frame(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
    t = glm::normalize(std::abs(n.z) < 0.9 ? glm::cross(n, glm::dvec3(0, 0, 1)) : glm::cross(n, glm::dvec3(1, 0, 0)));
    b = glm::cross(n, t);
}

}  // namespace ts
