#pragma once
// Light scattered more than once in the clear atmosphere, in Hillaire's approximation ("A
// Scalable and Production Ready Sky and Atmosphere Rendering Technique", EGSR 2020, section
// 5.5): at every point the light arriving after two or more scatterings is taken as isotropic,
// and its orders as a geometric series. Per wavelength, at altitude h with the sun at sine s:
//
//   L2(h, s)  = integral over the sphere of L1(h, w) / (4 pi) dw      (second order)
//   f(h)      = integral over the sphere of F1(h, w) / (4 pi) dw      (transfer of one order)
//   Psi(h, s) = L2 / (1 - f)                                          (all orders >= 2)
//
// where L1(h, w) is the light scattered once (isotropically) towards the point along w, plus the
// sunlit ground (Lambert, the sky's ground albedo) where w meets it, and F1(h, w) the integral of
// the scattering coefficient times the transmittance along w, plus the ground's albedo times its
// transmittance where w meets it (an isotropic unit radiance lights the ground with pi). Psi is
// radiance per unit of the sun's extraterrestrial irradiance; a view ray adds
// sigma_s(p) T(p) Psi(h(p), s(p)) along its length. The aerosol's forward peak is delta-scaled
// (medium()). Isotropy and one f per point are the approximation: against a path tracer of the
// same atmosphere the dome agrees with RMS 11% (physical_sky_test.cpp, docs/lighting.md),
// where single scattering alone is off by 230%.
//
// The table depends on the aerosol and the ground's albedo, not on where the sun is, so the
// skies of one atmosphere (a time-lapse's frames, a tile set's sun elevations) share it.
#include <memory>
#include <vector>

#include "core/light/atmosphere.hpp"

namespace ts::light {

class MultipleScattering {
public:
    static constexpr double kForwardFraction = atmosphere::kMieAsymmetry * atmosphere::kMieAsymmetry;
    static constexpr int kAltitudes = 12;  // 0..60 km, dense near the ground (h = H v^2)
    static constexpr int kSunSines = 40;   // sine of the sun's elevation, -0.35..1 uniformly
    static constexpr double kLowestSin = -0.35;

    MultipleScattering(const atmosphere::Coefficients& coefficients, double ground_albedo);
    // One table per atmosphere for the whole process: made on first use (~30 ms on one core),
    // then shared. The table is a pure function of its arguments, so sharing changes no result.
    static std::shared_ptr<const MultipleScattering> shared(const atmosphere::Aerosol& aerosol,
                                                            double ground_albedo);

    // The atmosphere as the table sees it: the aerosol's forward peak (a fraction
    // kForwardFraction of what it scatters) counted as light that goes on unscattered (delta-M
    // scaling), so what is left scatters nearly isotropically, as the approximation assumes.
    // A view ray gathers Psi through these coefficients.
    const atmosphere::Coefficients& medium() const { return medium_; }

    // Psi per wavelength, bilinear in (sqrt of altitude, sine of the sun's elevation).
    void at(double altitude_m, double sin_sun_elevation, atmosphere::Spectrum& out) const;

private:
    atmosphere::Coefficients medium_;
    std::vector<float> psi_;  // [altitude][sun sine][wavelength]
};

}  // namespace ts::light
