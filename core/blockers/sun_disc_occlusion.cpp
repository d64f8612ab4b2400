#include "core/blockers/sun_disc_occlusion.hpp"

#include "core/blockers/sphere_occlusion_shared.hpp"

namespace ts::blockers {

// The formulas are the text the flythrough's shaders compile (sphere_occlusion_shared.h).
double disc_overlap_area(double a, double b, double distance) { return shared::ts_disc_overlap_area(a, b, distance); }

double sun_disc_covered_fraction(double sun_radius, double cap_radius, double separation) {
    return shared::ts_sun_disc_covered_fraction(sun_radius, cap_radius, separation);
}

double sphere_sun_cover(const Sphere& sphere, const glm::dvec3& receiver, const glm::dvec3& sun,
                        double sun_radius) {
    return shared::ts_sphere_sun_cover(sphere.center, sphere.radius, receiver, sun, sun_radius);
}

double sphere_sky_cover(const Sphere& sphere, const glm::dvec3& receiver, const glm::dvec3& normal) {
    return shared::ts_sphere_sky_cover(sphere.center, sphere.radius, receiver, normal);
}

}  // namespace ts::blockers
