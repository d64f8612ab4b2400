#pragma once
// A product quadrature rule on the unit sphere: Gauss-Legendre in z = cos(theta) times the
// uniform (trapezoidal) rule in azimuth. With n_z nodes and n_phi azimuths it integrates
// exactly every polynomial of degree < min(2 n_z, n_phi) in (x, y, z); products of three
// order-4 SH functions (degree 9) need n_z >= 5 and n_phi >= 10.
#include <cstddef>
#include <glm/vec3.hpp>
#include <vector>

#include "core/sh/sh_basis.hpp"

namespace ts::sh {

class SphereQuadrature {
public:
    SphereQuadrature(int n_z, int n_phi);

    std::size_t size() const { return directions_.size(); }
    const std::vector<glm::dvec3>& directions() const { return directions_; }
    const std::vector<double>& weights() const { return weights_; }
    // The 16 basis values at point p (precomputed: projection is a weighted sum).
    const double* basis(std::size_t p) const { return &basis_[p * kCount]; }

    // SH coefficients of the function whose values at the rule's points are `values`.
    ShVec project_values(const std::vector<double>& values) const;
    // Values of the band-limited function f at every point.
    std::vector<double> reconstruct_values(const ShVec& f) const;

    template <class F>
    ShVec project(F&& f) const {
        std::vector<double> values(size());
        for (std::size_t p = 0; p < size(); ++p) values[p] = f(directions_[p]);
        return project_values(values);
    }
    template <class F>
    double integrate(F&& f) const {
        double s = 0.0;
        for (std::size_t p = 0; p < size(); ++p) s += weights_[p] * f(directions_[p]);
        return s;
    }

private:
    std::vector<glm::dvec3> directions_;
    std::vector<double> weights_;
    std::vector<double> basis_;
};

}  // namespace ts::sh
