#include "core/material/albedo.hpp"

#include "core/sh/gauss_legendre.hpp"
#include "core/util/angles.hpp"

namespace ts::material {

HemisphereRule cosine_hemisphere_rule(int n_cos, int n_phi) {
    const sh::GaussLegendre gl = sh::gauss_legendre(n_cos, 0.0, 1.0);
    HemisphereRule r;
    for (int i = 0; i < n_cos; ++i) {
        const double c = gl.nodes[i], s = std::sqrt(1.0 - c * c);
        for (int j = 0; j < n_phi; ++j) {
            const double phi = 2.0 * kPi * (j + 0.5) / n_phi;
            r.directions.emplace_back(s * std::cos(phi), s * std::sin(phi), c);
            r.weights.push_back(gl.weights[i] * 2.0 * kPi / n_phi * c);
        }
    }
    return r;
}

}  // namespace ts::material
