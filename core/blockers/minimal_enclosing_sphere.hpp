#pragma once
// The smallest sphere holding a set of points: Welzl's algorithm in its move-to-front form
// (recursion no deeper than the 4 support points), after a seeded shuffle. The radius is then
// reset to the largest distance from the centre found and padded by a relative 1e-9, so every
// point is inside whatever the rounding in the circumsphere formulas.
#include <span>

#include <glm/vec3.hpp>

#include "core/blockers/sphere_blocker.hpp"

namespace ts::blockers {

Sphere minimal_enclosing_sphere(std::span<const glm::dvec3> points);

// The smallest radius around a given centre holding every point, padded as above.
double enclosing_radius(std::span<const glm::dvec3> points, const glm::dvec3& center);

}  // namespace ts::blockers
