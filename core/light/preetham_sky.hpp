#pragma once
// Clear sky of Preetham, Shirley & Smits, "A practical analytic model for daylight",
// SIGGRAPH 1999: the Perez et al. (1993) all-weather distribution
//   F(theta, gamma) = (1 + A exp(B / cos theta)) (1 + C exp(D gamma) + E cos^2 gamma)
// for each of Y, x, y with coefficients linear in turbidity T, scaled by the zenith values
//   Y = Y_z F(theta, gamma) / F(0, theta_s)  (same for x, y),
// zenith luminance Y_z = (4.0453 T - 4.9710) tan chi - 0.2155 T + 2.4192 [kcd/m^2],
// chi = (4/9 - T/120)(pi - 2 theta_s), and zenith chromaticities from the paper's cubic fits
// in theta_s (theta: view zenith angle, gamma: angle to the sun, theta_s: sun zenith angle).
// The sun's disc is not in the sky radiance; see sun_transmittance.hpp.
#include <array>

#include "core/light/sky.hpp"

namespace ts::light {

// Perez coefficients A..E for one of Y, x, y.
using PerezCoefficients = std::array<double, 5>;
PerezCoefficients preetham_perez_luminance(double turbidity);
PerezCoefficients preetham_perez_x(double turbidity);
PerezCoefficients preetham_perez_y(double turbidity);
double perez(const PerezCoefficients& c, double cos_theta, double gamma);

// Zenith luminance (kcd/m^2) and chromaticity for a sun zenith angle theta_s in [0, pi/2].
double preetham_zenith_luminance(double turbidity, double sun_zenith_rad);
double preetham_zenith_x(double turbidity, double sun_zenith_rad);
double preetham_zenith_y(double turbidity, double sun_zenith_rad);

class PreethamSky final : public Sky {
public:
    // Turbidity 1.7..10 (parse_sky_options enforces it), ground albedo 0..1.
    PreethamSky(double turbidity, double ground_albedo, const glm::dvec3& sun_direction_enu);

    Rgb radiance(const glm::dvec3& dir) const override;
    SunDisc sun() const override { return sun_; }
    std::string describe() const override;

    // The sky dome alone (no ground), for directions with z > 0 (z is clamped to 1e-3 below).
    Rgb sky_radiance(const glm::dvec3& dir) const;
    // Radiance of the ground (below the horizon): albedo x horizontal irradiance / pi.
    Rgb ground_radiance() const { return ground_; }
    // Horizontal irradiance from the sky dome alone and from the sun's beam.
    Rgb sky_horizontal_irradiance() const { return sky_horizontal_; }
    // 1 when the sun is above the horizon; fades linearly to 0 at 6 degrees below (see below).
    double twilight_factor() const { return twilight_; }

private:
    double turbidity_;
    double albedo_;
    glm::dvec3 model_sun_;  // the sun the model is evaluated for (never below the horizon)
    PerezCoefficients cY_{}, cx_{}, cy_{};
    double zenith_Y_ = 0.0, zenith_x_ = 0.0, zenith_y_ = 0.0;
    double norm_Y_ = 1.0, norm_x_ = 1.0, norm_y_ = 1.0;  // F(0, theta_s)
    double twilight_ = 1.0;
    SunDisc sun_;
    Rgb sky_horizontal_{0.0f};
    Rgb ground_{0.0f};
};

}  // namespace ts::light
