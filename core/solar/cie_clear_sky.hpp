#pragma once
// The shape of the clear sky's diffuse radiance: the CIE standard general sky of type 12,
// "CIE standard clear sky, low illuminance turbidity" (ISO 15469:2004 / CIE S 011/E:2003; the
// CIE clear sky of 1973), the standard of daylighting and solar engineering. Relative radiance
// in direction w with the sun in direction s (unit ENU vectors):
//   L(w) ~ f(chi) * phi(Z),  chi = angle(w, s),  Z = zenith angle of w,
//   f(chi) = 1 + 10 (exp(-3 chi) - exp(-3 pi / 2)) + 0.45 cos^2 chi   (scattering indicatrix)
//   phi(Z) = 1 - exp(-0.32 / cos Z)                                      (gradation)
// It brightens around the sun (circumsolar) and towards the horizon, so a texel whose horizons
// hide the sun's side of the sky loses more diffuse light than an isotropic sky says. The
// amount is not the model's: the insolation scales it so that a horizontal plane under the open
// sky receives ESRA's diffuse irradiance (esra_clear_sky.hpp).
#include <glm/vec3.hpp>

namespace ts::solar {

// Relative radiance (unitless, ~1 at the zenith of a high sun). Below the horizon (w.z <= 0) the
// horizon's gradation holds: a texel above its surroundings sees sky there.
double cie_clear_sky_radiance(const glm::dvec3& sun, const glm::dvec3& w);
// Its two factors: f(chi) of the cosine of the angle to the sun, phi(Z) of w.z = cos Z.
double cie_clear_sky_indicatrix(double cos_chi);
double cie_clear_sky_gradation(double cos_zenith);

// The irradiance that radiance gives a horizontal plane, integral of L(w) w.z over the upper
// hemisphere, for a sun at elevation e (radians), by a fine quadrature: the normalisation of
// the shape. Slow (~10^5 evaluations); for references and tests.
double cie_clear_sky_horizontal_integral(double sun_elevation_rad);

}  // namespace ts::solar
