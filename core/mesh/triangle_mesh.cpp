#include "core/mesh/triangle_mesh.hpp"

#include <algorithm>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace ts::mesh {

Bounds mesh_bounds(const TriangleMesh& mesh) {
    if (mesh.positions.empty()) return {};
    Bounds b{glm::dvec3(std::numeric_limits<double>::max()), glm::dvec3(std::numeric_limits<double>::lowest())};
    for (const glm::vec3& p : mesh.positions) {
        b.lo = glm::min(b.lo, glm::dvec3(p));
        b.hi = glm::max(b.hi, glm::dvec3(p));
    }
    return b;
}

double triangle_area(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    return 0.5 * glm::length(glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a)));
}

double surface_area(const TriangleMesh& mesh) {
    double area = 0.0;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
        area += triangle_area(mesh.positions[3 * t], mesh.positions[3 * t + 1], mesh.positions[3 * t + 2]);
    return area;
}

}  // namespace ts::mesh
