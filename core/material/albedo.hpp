#pragma once
// Directional albedo a(wi) = int_{H+} f_r(wi, wo) cos(theta_o) dwo by a product rule over the
// outgoing hemisphere: Gauss-Legendre in cos(theta_o) on [0, 1] times the uniform rule in
// azimuth (local frame with z = n). Used by the energy-conservation tests and docs.
#include <cmath>
#include <glm/vec3.hpp>
#include <vector>

namespace ts::material {

struct HemisphereRule {
    std::vector<glm::dvec3> directions;  // in the local frame, z = normal
    std::vector<double> weights;         // include the cos(theta_o) factor
};

HemisphereRule cosine_hemisphere_rule(int n_cos, int n_phi);

template <class Brdf>
double directional_albedo(Brdf&& f, const glm::dvec3& wi, const HemisphereRule& rule) {
    double s = 0.0;
    for (std::size_t p = 0; p < rule.directions.size(); ++p) s += rule.weights[p] * f(wi, rule.directions[p]);
    return s;
}

}  // namespace ts::material
