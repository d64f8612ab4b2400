#include "core/solar/esra_clear_sky.hpp"

#include <cmath>

#include "core/util/angles.hpp"

namespace ts::solar {

double extraterrestrial_normal_irradiance(double day_of_year) {
    return kSolarConstantWm2 * (1.0 + 0.03344 * std::cos(2.0 * kPi * day_of_year / 365.25 - 0.048869));
}

double esra_refracted_altitude_rad(double h0) {
    const double num = 0.1594 + h0 * (1.123 + 0.065656 * h0);
    const double den = 1.0 + h0 * (28.9344 + 277.3971 * h0);
    return h0 + 0.061359 * num / den;
}

double relative_optical_air_mass(double altitude_rad, double elevation_m) {
    const double href = esra_refracted_altitude_rad(altitude_rad);
    return std::exp(-elevation_m / 8434.5) /
           (std::sin(href) + 0.50572 * std::pow(degrees(href) + 6.07995, -1.6364));
}

double rayleigh_optical_thickness(double m) {
    if (m <= 20.0) return 1.0 / (6.6296 + m * (1.7513 + m * (-0.1202 + m * (0.0065 - m * 0.00013))));
    return 1.0 / (10.4 + 0.718 * m);
}

double beam_normal_irradiance(double g0, double linke, double altitude_rad, double elevation_m) {
    if (!(altitude_rad > 0)) return 0.0;
    const double m = relative_optical_air_mass(altitude_rad, elevation_m);
    return g0 * std::exp(-0.8662 * linke * m * rayleigh_optical_thickness(m));
}

double diffuse_transmission(double tl) {
    return -0.015843 + tl * (0.030543 + 0.0003797 * tl);
}

double diffuse_angular_function(double tl, double altitude_rad) {
    const double tn = diffuse_transmission(tl);
    const double a1b = 0.26463 + tl * (-0.061581 + 0.0031408 * tl);
    const double a1 = a1b * tn < 0.0022 ? 0.0022 / tn : a1b;
    const double a2 = 2.04020 + tl * (0.018945 - 0.011161 * tl);
    const double a3 = -1.3025 + tl * (0.039231 + 0.0085079 * tl);
    const double s = std::sin(altitude_rad);
    return a1 + a2 * s + a3 * s * s;
}

double diffuse_horizontal_irradiance(double g0, double linke, double altitude_rad) {
    if (!(altitude_rad > 0)) return 0.0;
    return g0 * diffuse_transmission(linke) * diffuse_angular_function(linke, altitude_rad);
}

}  // namespace ts::solar
