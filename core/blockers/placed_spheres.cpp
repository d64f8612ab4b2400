#include "core/blockers/placed_spheres.hpp"

#include <algorithm>
#include <cmath>

#include <glm/matrix.hpp>

#include "core/util/angles.hpp"

namespace ts::blockers {

std::size_t SphereBlockers::sphere_count() const {
    std::size_t n = 0;
    for (const PlacedSpheres& m : meshes) n += m.spheres.size();
    return n;
}

PlacedSpheres place_spheres(std::span<const Sphere> model_spheres, const mesh::Placement& placement,
                            glm::dvec2 anchor, double ground_height_m, std::string name) {
    mesh::validate(placement);
    const glm::dmat3 rotation = mesh::placement_rotation(placement);
    const double lift = placement.height_m + (placement.above_ground ? ground_height_m : 0.0);
    PlacedSpheres p;
    p.name = std::move(name);
    p.anchor = anchor;
    p.spheres.reserve(model_spheres.size());
    for (const Sphere& s : model_spheres) {
        glm::dvec3 c = rotation * (s.center * placement.scale);
        c.z += lift;
        p.spheres.push_back({c, s.radius * placement.scale});
    }
    p.hierarchy = build_sphere_hierarchy(p.spheres);
    p.frame_to_model = glm::transpose(rotation) * (1.0 / placement.scale);
    p.model_origin = {0.0, 0.0, lift};
    return p;
}

std::shared_ptr<const TriangleBvh> model_triangle_bvh(const mesh::TriangleMesh& mesh) {
    const std::vector<glm::dvec3> p(mesh.positions.begin(), mesh.positions.end());
    return std::make_shared<const TriangleBvh>(p);
}

double min_cap_sine(double min_solid_angle_sr) {
    const double cos_min = 1.0 - std::clamp(min_solid_angle_sr, 0.0, 2.0 * kPi) / (2.0 * kPi);
    return std::sqrt(std::max(0.0, 1.0 - cos_min * cos_min));
}

}  // namespace ts::blockers
