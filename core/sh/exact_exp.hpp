#pragma once
// The reference for SH exponentiation: exp applied pointwise to the band-limited log function
// on a fine product quadrature grid, then projected to order 4. In double; the largest log
// value is factored out before exp (and capped at 700) so the reference never overflows.
#include "core/sh/sh_basis.hpp"
#include "core/sh/sphere_quadrature.hpp"

namespace ts::sh {

class ExactExp {
public:
    // 48 x 96 points integrate exp(f) to ~1e-9 relative for log magnitudes up to ~100.
    explicit ExactExp(int n_z = 48, int n_phi = 96);

    ShVec operator()(const ShVec& f_log) const;

    struct Range {
        double min, max;
    };
    // Smallest and largest value of the band-limited function f over the grid.
    Range range(const ShVec& f) const;

    const SphereQuadrature& quadrature() const { return quad_; }

private:
    SphereQuadrature quad_;
};

}  // namespace ts::sh
