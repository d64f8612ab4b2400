#pragma once
// Colour conversions for the sky models: CIE xyY to linear sRGB (Rec. 709 primaries, D65 white).
#include "core/light/sky.hpp"

namespace ts::light {

// CIE 1931 XYZ to linear Rec. 709 RGB (IEC 61966-2-1 matrix, D65 white). Out-of-gamut
// colours give negative channels; callers clamp.
Rgb xyz_to_linear_srgb(double X, double Y, double Z);

// Chromaticity (x, y) and luminance Y to linear sRGB, negative channels clamped to 0 (the
// Preetham chromaticities stay inside the gamut for the supported turbidities; the clamp only
// guards the extrapolated corners). y <= 0 gives black.
Rgb xyY_to_linear_srgb(double x, double y, double Y);

// Luminance of a linear sRGB colour (Rec. 709 weights): the Y the models are scaled in.
double luminance(const Rgb& rgb);

// Chromaticity of a black body at kelvin (4000..25000 K) on the CIE 1931 diagram, from the
// cubic-spline fit of Kim et al. (US patent 7024034, 2006; the standard approximation of the
// Planckian locus).
struct Chromaticity {
    double x = 0.0;
    double y = 0.0;
};
Chromaticity planckian_chromaticity(double kelvin);
// CIE 1931 xy of a linear Rec. 709 colour (the inverse of xyz_to_linear_srgb's matrix).
Chromaticity chromaticity_of(const Rgb& linear_srgb);

}  // namespace ts::light

namespace ts::light {

// The CIE 1931 2-degree colour-matching functions (x-bar, y-bar, z-bar) at a wavelength in nm,
// from the multi-lobe piecewise-Gaussian fit of Wyman, Sloan & Shirley, "Simple analytic
// approximations to the CIE XYZ color matching functions", JCGT 2(2) 2013 (their fit's error
// is within the spread between the CIE's own tabulations).
glm::dvec3 cie_1931_color_matching(double wavelength_nm);

}  // namespace ts::light
