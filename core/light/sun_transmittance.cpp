#include "core/light/sun_transmittance.hpp"

#include <algorithm>
#include <cmath>

#include "core/light/sky_color.hpp"
#include "core/util/angles.hpp"

namespace ts::light {

double kasten_young_air_mass(double zenith_deg) {
    const double z = std::clamp(std::isfinite(zenith_deg) ? zenith_deg : 90.0, 0.0, 90.0);
    const double cos_z = std::cos(z * kPi / 180.0);
    return 1.0 / (cos_z + 0.50572 * std::pow(96.07995 - z, -1.6364));
}

double angstrom_beta(double turbidity) {
    return std::max(0.0, 0.04608 * turbidity - 0.04586);
}

double rayleigh_optical_depth(double lambda_um) {
    return 0.008735 * std::pow(lambda_um, -4.08);
}

double aerosol_optical_depth(double turbidity, double lambda_um) {
    return angstrom_beta(turbidity) * std::pow(lambda_um, -1.3);
}

Rgb sun_transmittance(double turbidity, double zenith_deg) {
    const double m = kasten_young_air_mass(zenith_deg);
    Rgb t(0.0f);
    for (int c = 0; c < 3; ++c) {
        const double lambda = kChannelWavelengthUm[c];
        const double tau = rayleigh_optical_depth(lambda) + aerosol_optical_depth(turbidity, lambda);
        t[c] = static_cast<float>(std::exp(-m * tau));
    }
    return t;
}

Rgb sun_beam_irradiance(double turbidity, const glm::dvec3& sun_direction_enu, double angular_radius_rad) {
    const double sin_elevation = std::clamp(sun_direction_enu.z, -1.0, 1.0);
    const double elevation = std::asin(sin_elevation);
    if (!(elevation >= -angular_radius_rad)) return Rgb(0.0f);
    const Chromaticity sun = planckian_chromaticity(kSunTemperatureK);
    const Rgb extraterrestrial = xyY_to_linear_srgb(sun.x, sun.y, kSolarIlluminanceKlx);
    const double zenith_deg = 90.0 - elevation * 180.0 / kPi;
    return extraterrestrial * sun_transmittance(turbidity, zenith_deg);
}

}  // namespace ts::light
