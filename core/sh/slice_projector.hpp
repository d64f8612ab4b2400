#pragma once
// Height-field log-visibility from D azimuthal slices -> 16 log-SH coefficients.
//
// Slice k lies at azimuth phi_k = 2 pi k / D (counter-clockwise from east, ENU) and has a
// horizon elevation sigma_k (radians, [-pi/2, pi/2]): the log-visibility of the slice is
// log_eps below the horizon and 0 above (sh_shared.h). Between two slices the log-visibility
// is blended linearly in azimuth; the SH projection of that model is linear in per-slice
// quantities, so it is one precomputed matrix (docs/method.md derives it):
//
//  * project(c): input the slides' 4 normalised-Legendre coefficients per slice (layout
//    c[4 k + l]). The slice's profile is its 4-term Legendre expansion; a 16 x 4D matrix.
//    Exact for m = 0 and |m| = 2; for odd m the 4 coefficients cannot carry the profile
//    exactly (P_l^1, P_3^3 are not polynomials in cos theta), see project_horizons.
//  * project_horizons(sigma): input the D horizon angles. Exact projection of the blended
//    binary slices: per slice 10 closed-form integrals (ts_slice_sh_integrals) weighted by a
//    precomputed 16 x D azimuth table. Preferred: exact and cheaper (16 mult-adds per slice).
#include <array>
#include <vector>

namespace ts::sh {

class SliceProjector {
public:
    // D >= 4 (the azimuthal resolution of order-4 SH needs at least 4 slices; up to any size).
    explicit SliceProjector(int slices);

    int slices() const { return slices_; }
    static double azimuth(int k, int slices);

    void project(const float* slice_coeffs_4xD, float* out16) const;
    std::array<float, 16> project(const float* slice_coeffs_4xD) const;
    void project_horizons(const float* sigma, float log_eps, float* out16) const;
    std::array<float, 16> project_horizons(const float* sigma, float log_eps) const;

    // Row-major 16 x 4D matrix of project().
    const std::vector<float>& matrix() const { return matrix_; }

private:
    int slices_;
    std::vector<float> matrix_;          // 16 x 4D
    std::vector<float> azimuth_weight_;  // D x 16: ts_slice_azimuth_weight(m(i), phi_k, delta)
};

// The 4 normalised-Legendre basis functions Phat_l(x) = sqrt((2l+1)/2) P_l(x), x = cos theta.
std::array<double, 4> normalized_legendre(double x);

}  // namespace ts::sh
