#pragma once
// Points uniformly distributed over a mesh's surface (probability proportional to area), from a
// seed, so coverage can be measured on samples the decomposition never saw.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/mesh/triangle_mesh.hpp"

namespace ts::mesh {

std::vector<glm::dvec3> sample_surface(const TriangleMesh& mesh, int count, std::uint64_t seed);

}  // namespace ts::mesh
