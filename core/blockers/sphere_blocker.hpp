#pragma once
// Sphere blockers [Ren et al. 2006; slides "Spherical Blocker Log SH Visibility"]: a sphere
// seen from a receiver blocks a cone of half-angle theta_b = asin(r/d); its log-visibility
// (log_eps inside the cone) has 4 analytic log-ZH coefficients (core/sh/sh_shared.h, the one
// definition shared with GLSL), turned to the direction of the sphere with the ZH rotation.
// A receiver inside the sphere (d <= r) is fully occluded: theta_b = pi, the cap covering the
// whole sphere.
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "core/sh/sh_basis.hpp"

namespace ts::blockers {

struct Sphere {
    glm::dvec3 center;
    double radius;
};

double sphere_theta_b(double radius, double distance);
// Solid angle of a cap of half-angle theta_b: 2 pi (1 - cos theta_b).
double cap_solid_angle(double theta_b);
sh::ZhVec sphere_log_zh(double theta_b, double log_eps);
sh::ShVec sphere_log_sh(const Sphere& sphere, const glm::dvec3& receiver, double log_eps);

// "Ratio attenuation" (slides): summing many overlapping blockers' logs makes large log
// vectors that SH exponentiation handles badly. Two controls, both on by default:
//  * cull: a blocker whose whole cap lies below the receiver's tangent plane (angle between
//    the normal and the sphere direction > 90 deg + theta_b) is skipped (weight 0);
//  * solid-angle ratio: when the kept caps claim more than the 2 pi sr of the upper
//    hemisphere, they necessarily overlap; every kept blocker is scaled by
//    2 pi / sum(cap solid angles) so the sum claims at most the hemisphere.
// (The slides name the idea without a formula; this is our reading, see docs/method.md.)
struct RatioAttenuation {
    bool cull_lower_hemisphere = true;
    bool solid_angle_ratio = true;
};

std::vector<double> ratio_attenuation_weights(std::span<const Sphere> spheres, const glm::dvec3& receiver,
                                              const glm::dvec3& normal, const RatioAttenuation& options = {});

// Sum over blockers of weight * sphere_log_sh.
sh::ShVec accumulate_blockers(std::span<const Sphere> spheres, const glm::dvec3& receiver, const glm::dvec3& normal,
                          double log_eps, const RatioAttenuation& options = {});

}  // namespace ts::blockers
