#pragma once
// Points spread evenly over the sun's disc, as unit directions: for the sun shadow rays of a
// mesh's triangles (receiver_blockers.hpp) and for their ray-traced reference
// (core/visibility/blocker_reference.hpp).
#include <vector>

#include <glm/vec3.hpp>

namespace ts::blockers {

// `count` area-uniform points of the disc of angular radius `radius` about the unit direction
// `sun` (a sunflower spiral: point i at radius sqrt((i + 1/2) / count), golden-angle turns).
std::vector<glm::dvec3> sun_disc_directions(const glm::dvec3& sun, double radius, int count);

}  // namespace ts::blockers
