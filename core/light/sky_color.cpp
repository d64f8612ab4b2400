#include "core/light/sky_color.hpp"

#include <algorithm>
#include <cmath>

namespace ts::light {

Rgb xyz_to_linear_srgb(double X, double Y, double Z) {
    return Rgb(static_cast<float>(3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z),
               static_cast<float>(-0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z),
               static_cast<float>(0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z));
}

Rgb xyY_to_linear_srgb(double x, double y, double Y) {
    if (!(y > 0.0) || !(Y > 0.0)) return Rgb(0.0f);
    const double X = x * Y / y;
    const double Z = (1.0 - x - y) * Y / y;
    const Rgb rgb = xyz_to_linear_srgb(X, Y, Z);
    return Rgb(std::max(rgb.r, 0.0f), std::max(rgb.g, 0.0f), std::max(rgb.b, 0.0f));
}

double luminance(const Rgb& rgb) {
    return 0.2126729 * rgb.r + 0.7151522 * rgb.g + 0.0721750 * rgb.b;
}

Chromaticity chromaticity_of(const Rgb& c) {
    const double X = 0.4124564 * c.r + 0.3575761 * c.g + 0.1804375 * c.b;
    const double Y = 0.2126729 * c.r + 0.7151522 * c.g + 0.0721750 * c.b;
    const double Z = 0.0193339 * c.r + 0.1191920 * c.g + 0.9503041 * c.b;
    return {X / (X + Y + Z), Y / (X + Y + Z)};
}

Chromaticity planckian_chromaticity(double kelvin) {
    const double t = std::clamp(kelvin, 4000.0, 25000.0);
    const double u = 1.0 / t;
    const double x = -3.0258469e9 * u * u * u + 2.1070379e6 * u * u + 0.2226347e3 * u + 0.240390;
    const double y = 3.0817580 * x * x * x - 5.87338670 * x * x + 3.75112997 * x - 0.37001483;
    return {x, y};
}

}  // namespace ts::light

namespace ts::light {

namespace {
// exp(-(x - mu)^2 / (2 sigma^2)) with one sigma below the mean and another above.
double split_gaussian(double x, double mu, double sigma_below, double sigma_above) {
    const double t = (x - mu) / (x < mu ? sigma_below : sigma_above);
    return std::exp(-0.5 * t * t);
}
}  // namespace

glm::dvec3 cie_1931_color_matching(double nm) {
    const double x = 1.056 * split_gaussian(nm, 599.8, 37.9, 31.0) + 0.362 * split_gaussian(nm, 442.0, 16.0, 26.7) -
                     0.065 * split_gaussian(nm, 501.1, 20.4, 26.2);
    const double y = 0.821 * split_gaussian(nm, 568.8, 46.9, 40.5) + 0.286 * split_gaussian(nm, 530.9, 16.3, 31.1);
    const double z = 1.217 * split_gaussian(nm, 437.0, 11.8, 36.0) + 0.681 * split_gaussian(nm, 459.0, 26.0, 13.8);
    return {x, y, z};
}

}  // namespace ts::light
