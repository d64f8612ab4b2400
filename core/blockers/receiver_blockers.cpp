#include "core/blockers/receiver_blockers.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "core/util/angles.hpp"

namespace ts::blockers {

void collect_sky_blockers(const PlacedSpheres& mesh, const glm::dvec3& receiver, const glm::dvec3& normal,
                          double min_sine, const RatioAttenuation& options, std::vector<Sphere>& out) {
    auto keep = [&](const Sphere& s) {
        const glm::dvec3 v = s.center - receiver;
        const double d2 = glm::dot(v, v);
        if (d2 <= s.radius * s.radius) return true;  // inside: the whole sphere of directions
        const double d = std::sqrt(d2);
        const double sin_b = s.radius / d;
        if (sin_b <= min_sine) return false;
        // Cap wholly below the tangent plane: the angle to the normal exceeds 90 deg + theta_b.
        return !(options.cull_lower_hemisphere && glm::dot(v, normal) / d < -sin_b);
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
