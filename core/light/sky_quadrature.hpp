#pragma once
// The deterministic quadrature every sky integral uses: the sphere split at the horizon (where
// the sky meets the ground and radiance jumps), Gauss-Legendre in z = cos(theta) on each half,
// uniform in azimuth. With n_z nodes per half and n_phi azimuths it integrates exactly every
// polynomial in (x, y, z) of degree < min(2 n_z, n_phi) on each hemisphere separately, so a
// function that is smooth on each half but jumps at the horizon is still integrated to
// high order.
#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>
#include <vector>

#include "core/sh/gauss_legendre.hpp"
#include "core/util/angles.hpp"

namespace ts::light {

struct HemisphereRule {
    int n_z = 64;     // Gauss-Legendre nodes in z per hemisphere
    int n_phi = 256;  // azimuths
};

// Calls f(direction, weight) for every node of the upper (z in [0, 1]) and, if `lower`, the
// lower hemisphere. Weights sum to 2 pi per hemisphere.
template <class F>
void for_each_sky_node(const HemisphereRule& rule, bool lower, F&& f) {
    const double dphi = 2.0 * kPi / rule.n_phi;
    // The azimuths are the same on every ring: their cos/sin once, not once per node.
    std::vector<double> cos_phi(std::size_t(std::max(0, rule.n_phi))), sin_phi(cos_phi.size());
    for (int j = 0; j < rule.n_phi; ++j) {
        // Half-step offset: no node exactly on an axis, where models are often special-cased.
        const double phi = (j + 0.5) * dphi;
        cos_phi[std::size_t(j)] = std::cos(phi);
        sin_phi[std::size_t(j)] = std::sin(phi);
    }
    for (int half = 0; half < (lower ? 2 : 1); ++half) {
        const sh::GaussLegendre gl =
            half == 0 ? sh::gauss_legendre(rule.n_z, 0.0, 1.0) : sh::gauss_legendre(rule.n_z, -1.0, 0.0);
        for (std::size_t k = 0; k < gl.nodes.size(); ++k) {
            const double z = gl.nodes[k];
            const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
            const double w = gl.weights[k] * dphi;
            for (int j = 0; j < rule.n_phi; ++j)
                f(glm::dvec3(r * cos_phi[std::size_t(j)], r * sin_phi[std::size_t(j)], z), w);
        }
    }
}

}  // namespace ts::light
