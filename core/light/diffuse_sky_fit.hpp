#pragma once
// The sky's SH as diffuse terrain needs it (docs/rendering.md, "The sky's SH for diffuse
// terrain"). Shading <T, L> with the sky's radiance projected on bands 0..2 gives an open
// texel the band-limited part of its irradiance; a clear sky's circumsolar peak puts part of
// that irradiance in band 4, which the nine coefficients drop: slopes facing the sun come out
// too dark and slopes facing away too bright (-1% and +1.6% of their radiance under a 20 degree
// sun, against Blender Cycles). Bands 0..2 are therefore fitted instead: the coefficients whose
// open-texel irradiance is the least-squares best over the normals terrain has, slopes up to
// kDiffuseFitMaxSlopeDeg, uniform in solid angle. For a sky whose radiance is band-limited to
// band 2 the fit is the projection; band 3 stays the projection.
//
// The fit is linear in the radiance, and with the fit's normals symmetric in azimuth each
// coefficient's weight on a quadrature ring of height z factors as F_i(z) trig_m(phi), as the
// projection's Y_i does: project_sky_sh's ring sums with F_i(z) in place of Y_i's factor.
//
//   F(z) = G^-1 h(z),  G_ij = int_cap t_i t_j dn,  h_i(z) trig_m(phi) = 1/pi int_cap t_i(n) max(0, n . d) dn,
//   t_i(n) = A_l / pi Y_i(n) (an open texel's transfer), d = (sqrt(1 - z^2) (cos phi, sin phi), z)
//
// h's azimuthal integral is in closed form; its integral over the cap's heights is Gauss-Legendre.
#include <array>

namespace ts::light {

// The steepest slope of the normals the fit serves. Chosen from the error against Blender Cycles
// on the held-out Anatolia crop (docs/rendering.md): 60 and 75 degrees within 0.02% of each
// other, 45 degrees 0.1% worse, 30 degrees worse than the projection (steep texels fall outside).
inline constexpr double kDiffuseFitMaxSlopeDeg = 60.0;

class DiffuseSkyFit {
public:
    DiffuseSkyFit();
    // F_i(z), i = 0..8: the weight of the ring sum sum_j w_j L_j trig_m(phi_j) on coefficient i.
    std::array<double, 9> ring_factors(double z) const;

private:
    std::array<double, 81> g_inverse_{};  // G^-1, row-major
    std::array<double, 48> u_{}, w_{};    // Gauss-Legendre heights of the cap's normals
    std::array<std::array<double, 9>, 48> radial_{};  // A_l / pi R_i(u): t_i without its trig_m
};

}  // namespace ts::light
