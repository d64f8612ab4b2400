#include "core/blockers/self_shadow.hpp"

#include <vector>

#include <glm/geometric.hpp>

#include "core/blockers/sun_disc_occlusion.hpp"

namespace ts::blockers {

bool sphere_contains(const Sphere& s, const glm::dvec3& p) {
    const glm::dvec3 d = p - s.center;
    // A relative 1e-9 as the decomposition pads its radii: surface corners count as inside.
    const double r = s.radius * (1.0 + 1e-9);
    return glm::dot(d, d) <= r * r;
}

sh::ShVec self_shadow_log_sh(std::span<const Sphere> spheres, const glm::dvec3& point, const glm::dvec3& normal,
                             double log_eps, const RatioAttenuation& options) {
    std::vector<Sphere> others;
    others.reserve(spheres.size());
    for (const Sphere& s : spheres)
        if (!sphere_contains(s, point)) others.push_back(s);
    if (others.empty()) return sh::ShVec{};
    return accumulate_blockers(others, point, normal, log_eps, options);
}

double self_shadow_sun(std::span<const Sphere> spheres, const glm::dvec3& point, const glm::dvec3& sun,
                       double sun_radius) {
    double visible = 1.0;
    for (const Sphere& s : spheres) {
        if (sphere_contains(s, point)) continue;
        visible *= 1.0 - sphere_sun_cover(s, point, sun, sun_radius);
        if (visible <= 0.0) return 0.0;
    }
    return visible;
}

}  // namespace ts::blockers
