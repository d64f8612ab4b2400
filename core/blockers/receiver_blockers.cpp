#include "core/blockers/receiver_blockers.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "core/util/angles.hpp"

namespace ts::blockers {

void collect_sky_blockers(const PlacedSpheres& mesh, const glm::dvec3& receiver, const glm::dvec3& normal,
                          double min_sine, const RatioAttenuation& options, std::vector<Sphere>& out) {
    if (mesh.hierarchy.nodes.empty()) return;
    // The threshold is the mesh's: its bounding sphere (the root) must subtend more than it. Per
    // sphere, a finer decomposition would lose shadow: 512 small spheres fall below a threshold
    // their union is far above. The root's cone holds every sphere's, so no sphere of a mesh
    // that fails could pass.
    const Sphere& root = mesh.hierarchy.nodes[0].bound;
    const glm::dvec3 rv = root.center - receiver;
    const double rd2 = glm::dot(rv, rv);
    if (rd2 > root.radius * root.radius && root.radius / std::sqrt(rd2) <= min_sine) return;
    auto keep = [&](const Sphere& s) {
        if (!options.cull_lower_hemisphere) return true;
        const glm::dvec3 v = s.center - receiver;
        const double d2 = glm::dot(v, v);
        if (d2 <= s.radius * s.radius) return true;  // inside: the whole sphere of directions
        const double d = std::sqrt(d2);
        // Cap wholly below the tangent plane: the angle to the normal exceeds 90 deg + theta_b.
        return !(glm::dot(v, normal) / d < -s.radius / d);
    };
    visit_leaves(mesh.hierarchy, keep, [&](int i) {
        const Sphere& s = mesh.spheres[std::size_t(i)];
        out.push_back({s.center - receiver, s.radius});
    });
}

double sun_visible_past(const PlacedSpheres& mesh, const glm::dvec3& receiver, const glm::dvec3& sun,
                        double sun_radius) {
    // A sphere whose cap stays sun_radius clear of the sun's centre hides none of the disc.
    auto keep = [&](const Sphere& s) {
        const glm::dvec3 v = s.center - receiver;
        const double d = glm::length(v);
        if (d <= s.radius) return true;
        const double cap = std::asin(s.radius / d);
        const double along = glm::dot(v, sun) / d;
        const double limit = cap + sun_radius;
        return limit >= kPi || along > std::cos(limit);
    };
    double visible = 1.0;
    visit_leaves(mesh.hierarchy, keep, [&](int i) {
        if (visible > 0.0) visible *= 1.0 - sphere_sun_cover(mesh.spheres[std::size_t(i)], receiver, sun, sun_radius);
    });
    return visible;
}

}  // namespace ts::blockers
