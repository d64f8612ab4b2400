#pragma once
// The sun's direct beam after the atmosphere, per RGB channel: the extraterrestrial solar
// illuminance, a colour, and Beer-Lambert transmittance along the relative air mass with
// Rayleigh and aerosol (Angstrom) optical depths at one wavelength per channel.
#include "core/light/sky.hpp"

namespace ts::light {

// Luminous solar constant, klx at 1 AU (Darula, Kittler & Gueymard, "Reference luminous solar
// constant and solar luminance for illuminance calculations", Solar Energy 79 (2005) 559-565:
// 133.8 klx).
inline constexpr double kSolarIlluminanceKlx = 133.8;
// The extraterrestrial sun's colour: a 5778 K black body.
inline constexpr double kSunTemperatureK = 5778.0;
// Effective wavelengths (micrometres) at which each Rec. 709 channel's optical depth is taken.
inline constexpr double kChannelWavelengthUm[3] = {0.610, 0.550, 0.465};

// Relative optical air mass at a true zenith angle (degrees), Kasten & Young, Applied Optics
// 28(22) 4735 (1989): 1/(cos z + 0.50572 (96.07995 - z)^-1.6364). Zenith clamped to [0, 90]
// (37.92 at the horizon), so it is finite for any input.
double kasten_young_air_mass(double zenith_deg);

// Angstrom's beta for a Linke-like turbidity T, the relation of Preetham et al. 1999
// (appendix): beta = 0.04608 T - 0.04586; alpha = 1.3.
double angstrom_beta(double turbidity);

// Vertical optical depths at wavelength lambda (micrometres): Rayleigh 0.008735 lambda^-4.08
// (Leckner 1978, as used by Iqbal and by Preetham's appendix) and aerosol beta lambda^-1.3.
double rayleigh_optical_depth(double lambda_um);
double aerosol_optical_depth(double turbidity, double lambda_um);

// Per-channel transmittance of the direct beam at a sun zenith angle (degrees).
Rgb sun_transmittance(double turbidity, double zenith_deg);

// Irradiance (klx-like units: kcd/m^2 x sr) of the sun's beam on a plane facing it, linear RGB,
// after the atmosphere; 0 when the disc is wholly below the mathematical horizon
// (elevation < -angular radius). Never NaN.
Rgb sun_beam_irradiance(double turbidity, const glm::dvec3& sun_direction_enu, double angular_radius_rad);

}  // namespace ts::light
