#pragma once
// The clear atmosphere shared by the physical sky's single- and multiple-scattering parts:
// a spherical Earth with air (Rayleigh) and aerosol (Mie) thinning exponentially with
// altitude and an ozone layer, its per-wavelength coefficients, and the optical depth towards
// the sun from any point. Constants and their sources: docs/lighting.md, "Physical clear sky".
#include <array>
#include <vector>

namespace ts::light::atmosphere {

// Bruneton & Neyret (2008)'s radii and scale heights.
inline constexpr double kEarthRadiusM = 6360e3;
inline constexpr double kTopRadiusM = 6420e3;
inline constexpr double kHeightM = kTopRadiusM - kEarthRadiusM;
inline constexpr double kRayleighScaleHeightM = 8000.0;
inline constexpr double kMieScaleHeightM = 1200.0;
// Cornette & Shanks (1992)'s phase function with a continental aerosol's asymmetry; the
// aerosol scatters 90% of what it takes out of a beam (the rest is absorbed).
inline constexpr double kMieAsymmetry = 0.76;
inline constexpr double kAerosolSingleScatteringAlbedo = 0.9;

// Wavelengths (nm) at which the spectrum is sampled.
inline constexpr int kWavelengths = 17;
inline constexpr double kFirstWavelengthNm = 390.0;
inline constexpr double kWavelengthStepNm = 20.0;
inline double wavelength_nm(int k) {
    return kFirstWavelengthNm + k * kWavelengthStepNm;
}
using Spectrum = std::array<float, kWavelengths>;

// The aerosol's vertical optical depth beta lambda^-alpha (lambda in micrometres, Angstrom).
struct Aerosol {
    double beta = 0.0;
    double alpha = 1.3;
};

// Per metre at sea level (air, aerosol) and per unit of the ozone layer's column. In float:
// the spectral loops (17 exponentials a step, most of a sky's cost) run in float.
struct Coefficients {
    Spectrum rayleigh{}, mie_scattering{}, mie_extinction{}, ozone{};
};
Coefficients coefficients_for(const Aerosol& aerosol);

// Densities relative to sea level; ozone's per metre of its column (its vertical integral is 1).
struct Densities {
    double rayleigh = 0.0, mie = 0.0, ozone = 0.0;
};
Densities densities_at(double altitude_m);

// Distance from radius r along cos(zenith) mu to the top of the atmosphere; negative when the
// ray meets the ground first.
double distance_to_top(double r, double mu);
// Distance from radius r along cos(zenith) mu to the ground; negative when the ray misses it.
double distance_to_ground(double r, double mu);

// Densities integrated from radius r along cos(zenith) mu to the top (which the ray must reach).
Densities optical_path(double r, double mu, int steps);

// The integrated densities towards the sun from any point, over altitude and the sun's
// elevation there. It depends on nothing but the constants above, so it is made once per
// process and shared (immutable after construction).
class SunPathTable {
public:
    static constexpr int kAltitudes = 48;
    // Uniform in the sine of the elevation from -0.35 (-20.5 degrees): steps of 0.25 degree at
    // the horizon, where the path changes fastest, and no asin per look-up.
    static constexpr int kElevations = 541;
    static constexpr double kLowestSin = -0.35;
    static constexpr double kStepSin = 1.35 / (kElevations - 1);
    // A depth that stands for "the Earth is in the way": exp(-it) is 0 for every coefficient.
    static constexpr double kBlocked = 1e12;

    static const SunPathTable& instance();
    // Bilinear in (sqrt of altitude, elevation).
    Densities at(double altitude_m, double sin_elevation) const;
    static bool blocked(const Densities& d) { return d.rayleigh > 1e-3 * kBlocked; }

private:
    SunPathTable();
    std::vector<Densities> paths_;
};

}  // namespace ts::light::atmosphere
