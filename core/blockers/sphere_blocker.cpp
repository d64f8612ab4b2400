#include "core/blockers/sphere_blocker.hpp"

#include <cmath>
#include <glm/geometric.hpp>

#include "core/sh/sh_shared.hpp"

namespace ts::blockers {

using sh::ShVec;
using sh::ZhVec;
using sh::operator+;  // ShVec is a std::array: its operators are found by name, not ADL
using sh::operator*;

double sphere_theta_b(double radius, double distance) {
    return sh::shared::ts_sphere_theta_b(radius, distance);
}

double cap_solid_angle(double theta_b) {
    return 2.0 * kPi * (1.0 - std::cos(theta_b));
}

ZhVec sphere_log_zh(double theta_b, double log_eps) {
    double c[4];
    sh::shared::ts_sphere_log_zh(theta_b, log_eps, c);
    return {c[0], c[1], c[2], c[3]};
}

ShVec sphere_log_sh(const Sphere& sphere, const glm::dvec3& receiver, double log_eps) {
    const glm::dvec3 v = sphere.center - receiver;
    const double d = glm::length(v);
    const double tb = sphere_theta_b(sphere.radius, d);
    // Inside the sphere the cap is the whole sphere: any axis will do.
    const glm::dvec3 dir = d > 0.0 ? v / d : glm::dvec3(0.0, 0.0, 1.0);
    return sh::zh_rotate(sphere_log_zh(tb, log_eps), dir);
}

std::vector<double> ratio_attenuation_weights(std::span<const Sphere> spheres, const glm::dvec3& receiver,
                                              const glm::dvec3& normal, const RatioAttenuation& options) {
    std::vector<double> w(spheres.size(), 1.0);
    double total = 0.0;
    for (std::size_t b = 0; b < spheres.size(); ++b) {
        const glm::dvec3 v = spheres[b].center - receiver;
        const double d = glm::length(v);
        const double tb = sphere_theta_b(spheres[b].radius, d);
        if (options.cull_lower_hemisphere && tb < kPi) {
            // Cap entirely below the tangent plane: angle to the normal > pi/2 + theta_b,
            // i.e. cos(angle) < -sin(theta_b).
            const double cos_angle = glm::dot(v / d, normal);
            if (cos_angle < -std::sin(tb)) {
                w[b] = 0.0;
                continue;
            }
        }
        total += cap_solid_angle(tb);
    }
    if (options.solid_angle_ratio && total > 2.0 * kPi) {
        const double ratio = 2.0 * kPi / total;
        for (double& x : w) x *= ratio;
    }
    return w;
}

ShVec accumulate_blockers(std::span<const Sphere> spheres, const glm::dvec3& receiver, const glm::dvec3& normal,
                          double log_eps, const RatioAttenuation& options) {
    const std::vector<double> w = ratio_attenuation_weights(spheres, receiver, normal, options);
    ShVec f{};
    for (std::size_t b = 0; b < spheres.size(); ++b) {
        if (w[b] == 0.0) continue;
        f = f + w[b] * sphere_log_sh(spheres[b], receiver, log_eps);
    }
    return f;
}

}  // namespace ts::blockers
