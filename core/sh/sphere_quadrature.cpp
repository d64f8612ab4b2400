#include "core/sh/sphere_quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/sh/gauss_legendre.hpp"

namespace ts::sh {

SphereQuadrature::SphereQuadrature(int n_z, int n_phi) {
    if (n_z < 1 || n_phi < 1) throw std::invalid_argument("SphereQuadrature: empty rule");
    const GaussLegendre gl = gauss_legendre(n_z);
    const double dphi = 2.0 * kPi / n_phi;
    directions_.reserve(static_cast<std::size_t>(n_z) * n_phi);
    for (int i = 0; i < n_z; ++i) {
        const double z = gl.nodes[i];
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        for (int j = 0; j < n_phi; ++j) {
            const double phi = (j + 0.5) * dphi;
            directions_.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
            weights_.push_back(gl.weights[i] * dphi);
        }
    }
    basis_.resize(directions_.size() * kCount);
    for (std::size_t p = 0; p < directions_.size(); ++p) {
        const ShVec y = eval(directions_[p]);
        for (int k = 0; k < kCount; ++k) basis_[p * kCount + k] = y[k];
    }
}

ShVec SphereQuadrature::project_values(const std::vector<double>& values) const {
    if (values.size() != size()) throw std::invalid_argument("SphereQuadrature: value count");
    ShVec f{};
    for (std::size_t p = 0; p < size(); ++p) {
        const double wv = weights_[p] * values[p];
        const double* y = basis(p);
        for (int k = 0; k < kCount; ++k) f[k] += wv * y[k];
    }
    return f;
}

std::vector<double> SphereQuadrature::reconstruct_values(const ShVec& f) const {
    std::vector<double> v(size());
    for (std::size_t p = 0; p < size(); ++p) {
        const double* y = basis(p);
        double s = 0.0;
        for (int k = 0; k < kCount; ++k) s += f[k] * y[k];
        v[p] = s;
    }
    return v;
}

}  // namespace ts::sh
