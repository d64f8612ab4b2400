#include "core/blockers/sun_disc_occlusion.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/util/angles.hpp"

namespace ts::blockers {

double disc_overlap_area(double a, double b, double distance) {
    const double d = distance;
    if (d >= a + b) return 0.0;
    const double small = std::min(a, b);
    if (d <= std::abs(a - b)) return kPi * small * small;
    // Two circular segments cut by the common chord; x_a, x_b are the chord's distances from
    // each centre (signed: negative when the chord lies beyond the centre).
    const double x_a = (d * d + a * a - b * b) / (2.0 * d);
    const double x_b = d - x_a;
    auto segment = [](double r, double x) {
        const double c = std::clamp(x / r, -1.0, 1.0);
        return r * r * std::acos(c) - x * std::sqrt(std::max(0.0, r * r - x * x));
    };
    return std::clamp(segment(a, x_a) + segment(b, x_b), 0.0, kPi * small * small);
}

double sun_disc_covered_fraction(double sun_radius, double cap_radius, double separation) {
    if (separation >= cap_radius + sun_radius) return 0.0;
    if (separation <= cap_radius - sun_radius) return 1.0;
    return disc_overlap_area(sun_radius, cap_radius, separation) / (kPi * sun_radius * sun_radius);
}

double sphere_sun_cover(const Sphere& sphere, const glm::dvec3& receiver, const glm::dvec3& sun,
                        double sun_radius) {
    const glm::dvec3 v = sphere.center - receiver;
    const double d = glm::length(v);
    if (d <= sphere.radius) return 1.0;
    const double cap = std::asin(sphere.radius / d);
    // The angle between two unit vectors by atan2 keeps its precision near 0 (acos does not).
    const glm::dvec3 u = v / d;
    const double separation = std::atan2(glm::length(glm::cross(u, sun)), glm::dot(u, sun));
    return sun_disc_covered_fraction(sun_radius, cap, separation);
}

}  // namespace ts::blockers
