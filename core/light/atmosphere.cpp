#include "core/light/atmosphere.hpp"

#include <algorithm>
#include <cmath>

#include "core/light/sun_transmittance.hpp"

namespace ts::light::atmosphere {

namespace {

// Ozone: 300 Dobson units (2.687e20 molecules/m^2 each) in a layer peaking at 25 km and gone
// at 10 and 40 km; its Chappuis band as a split Gaussian, 5.0e-25 m^2 at 603 nm, falling to
// half 75 nm below and 58 nm above (a fit to the band's measured cross-sections).
constexpr double kOzoneColumnPerM2 = 300.0 * 2.687e20;
constexpr double kOzonePeakM = 25e3;
constexpr double kOzoneHalfWidthM = 15e3;
double ozone_cross_section_m2(double nm) {
    const double sigma = nm < 603.0 ? 75.0 / 1.1774 : 58.0 / 1.1774;
    const double t = (nm - 603.0) / sigma;
    return 5.0e-25 * std::exp(-0.5 * t * t);
}

double altitude_of_row(int i) {
    const double v = double(i) / (SunPathTable::kAltitudes - 1);
    return kHeightM * v * v;
}

}  // namespace

Coefficients coefficients_for(const Aerosol& aerosol) {
    // Air's and aerosol's vertical optical depths are those of the sun's beam model
    // (sun_transmittance.hpp) spread over their scale heights, so a turbidity means the same
    // aerosol load for the disc and the dome.
    Coefficients c;
    for (int k = 0; k < kWavelengths; ++k) {
        const std::size_t kk = std::size_t(k);
        const double nm = wavelength_nm(k);
        const double um = nm * 1e-3;
        const double mie = aerosol.beta * std::pow(um, -aerosol.alpha) / kMieScaleHeightM;
        c.rayleigh[kk] = float(rayleigh_optical_depth(um) / kRayleighScaleHeightM);
        c.mie_extinction[kk] = float(mie);
        c.mie_scattering[kk] = float(kAerosolSingleScatteringAlbedo * mie);
        c.ozone[kk] = float(ozone_cross_section_m2(nm) * kOzoneColumnPerM2);
    }
    return c;
}

Densities densities_at(double altitude_m) {
    const double h = std::max(altitude_m, 0.0);
    return {std::exp(float(-h / kRayleighScaleHeightM)), std::exp(float(-h / kMieScaleHeightM)),
            std::max(0.0, 1.0 - std::abs(h - kOzonePeakM) / kOzoneHalfWidthM) / kOzoneHalfWidthM};
}

double distance_to_top(double r, double mu) {
    const double ground = r * r * (mu * mu - 1.0) + kEarthRadiusM * kEarthRadiusM;
    if (mu < 0.0 && ground >= 0.0) return -1.0;
    return -r * mu + std::sqrt(std::max(0.0, r * r * (mu * mu - 1.0) + kTopRadiusM * kTopRadiusM));
}

double distance_to_ground(double r, double mu) {
    const double ground = r * r * (mu * mu - 1.0) + kEarthRadiusM * kEarthRadiusM;
    if (mu >= 0.0 || ground < 0.0) return -1.0;
    return -r * mu - std::sqrt(ground);
}

// Steps dense near the start, where the density is highest (t = d u^2).
Densities optical_path(double r, double mu, int steps) {
    const double d = distance_to_top(r, mu);
    Densities sum;
    for (int k = 0; k < steps; ++k) {
        const double u = (k + 0.5) / steps;
        const double t = d * u * u;
        const double dt = 2.0 * d * u / steps;
        const double rr = std::sqrt(r * r + t * t + 2.0 * r * t * mu);
        const Densities rho = densities_at(rr - kEarthRadiusM);
        sum.rayleigh += rho.rayleigh * dt;
        sum.mie += rho.mie * dt;
        sum.ozone += rho.ozone * dt;
    }
    return sum;
}

SunPathTable::SunPathTable() : paths_(std::size_t(kAltitudes) * kElevations) {
    for (int i = 0; i < kAltitudes; ++i) {
        const double r = kEarthRadiusM + altitude_of_row(i);
        for (int j = 0; j < kElevations; ++j) {
            const double mu = kLowestSin + j * kStepSin;
            paths_[std::size_t(i) * kElevations + std::size_t(j)] =
                distance_to_top(r, mu) < 0.0 ? Densities{kBlocked, kBlocked, kBlocked} : optical_path(r, mu, 96);
        }
    }
}

const SunPathTable& SunPathTable::instance() {
    static const SunPathTable table;
    return table;
}

Densities SunPathTable::at(double altitude_m, double sin_elevation) const {
    const double h = altitude_m > 0.0 ? std::min(altitude_m, kHeightM) : 0.0;  // NaN -> 0
    const double a = std::sqrt(h / kHeightM) * (kAltitudes - 1);
    const double e = (std::min(sin_elevation, 1.0) - kLowestSin) / kStepSin;
    if (!(e >= 0.0)) return {kBlocked, kBlocked, kBlocked};  // below the table, or NaN
    const int i = std::min(int(a), kAltitudes - 2);
    const int j = std::min(int(e), kElevations - 2);
    const double fa = std::min(a - i, 1.0), fe = std::min(e - j, 1.0);
    auto p = [&](int di, int dj) { return paths_[std::size_t(i + di) * kElevations + std::size_t(j + dj)]; };
    const double w00 = (1 - fa) * (1 - fe), w01 = (1 - fa) * fe, w10 = fa * (1 - fe), w11 = fa * fe;
    Densities out;
    out.rayleigh = w00 * p(0, 0).rayleigh + w01 * p(0, 1).rayleigh + w10 * p(1, 0).rayleigh + w11 * p(1, 1).rayleigh;
    out.mie = w00 * p(0, 0).mie + w01 * p(0, 1).mie + w10 * p(1, 0).mie + w11 * p(1, 1).mie;
    out.ozone = w00 * p(0, 0).ozone + w01 * p(0, 1).ozone + w10 * p(1, 0).ozone + w11 * p(1, 1).ozone;
    return out;
}

}  // namespace ts::light::atmosphere
