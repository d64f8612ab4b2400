#include "core/light/preetham_sky.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/light/sky_color.hpp"
#include "core/light/sky_quadrature.hpp"
#include "core/light/sun_transmittance.hpp"
#include "core/util/angles.hpp"

namespace ts::light {

namespace {

// Perez coefficients = a T + b, Preetham et al. 1999, appendix A.2.
PerezCoefficients linear_in_t(const double (&a)[5], const double (&b)[5], double t) {
    PerezCoefficients c{};
    for (int i = 0; i < 5; ++i) c[i] = a[i] * t + b[i];
    return c;
}

// [T^2 T 1] M [theta^3 theta^2 theta 1]^T, the zenith chromaticity fits (appendix A.2).
double zenith_chromaticity(const double (&m)[3][4], double t, double theta) {
    const double tv[3] = {t * t, t, 1.0};
    const double sv[4] = {theta * theta * theta, theta * theta, theta, 1.0};
    double s = 0.0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j) s += tv[i] * m[i][j] * sv[j];
    }
    return s;
}

// How far below the horizon (degrees) the sky fades to black. The Preetham model is fitted
// only for the sun above the horizon; below, it is evaluated for the sun on the horizon and
// dimmed linearly to 0 at the end of civil twilight (-6 degrees). Not physical (a real
// twilight sky turns blue-violet and its zenith stays brightest); it keeps dawn sequences
// continuous and finite.
constexpr double kTwilightDepthDeg = 6.0;
}  // namespace

PerezCoefficients preetham_perez_luminance(double t) {
    return linear_in_t({0.1787, -0.3554, -0.0227, 0.1206, -0.0670}, {-1.4630, 0.4275, 5.3251, -2.5771, 0.3703}, t);
}
PerezCoefficients preetham_perez_x(double t) {
    return linear_in_t({-0.0193, -0.0665, -0.0004, -0.0641, -0.0033}, {-0.2592, 0.0008, 0.2125, -0.8989, 0.0452}, t);
}
PerezCoefficients preetham_perez_y(double t) {
    return linear_in_t({-0.0167, -0.0950, -0.0079, -0.0441, -0.0109}, {-0.2608, 0.0092, 0.2102, -1.6537, 0.0529}, t);
}

double perez(const PerezCoefficients& c, double cos_theta, double gamma) {
    // cos theta clamped away from 0: B / cos theta -> -inf at the horizon, and exp of it -> 0,
    // which is the right limit for B < 0 (all supported turbidities); the clamp avoids 0/0.
    const double ct = std::max(cos_theta, 1e-3);
    const double cg = std::cos(gamma);
    return (1.0 + c[0] * std::exp(c[1] / ct)) * (1.0 + c[2] * std::exp(c[3] * gamma) + c[4] * cg * cg);
}

double preetham_zenith_luminance(double t, double theta_s) {
    const double chi = (4.0 / 9.0 - t / 120.0) * (kPi - 2.0 * theta_s);
    return (4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192;
}

double preetham_zenith_x(double t, double theta_s) {
    static constexpr double m[3][4] = {{0.00166, -0.00375, 0.00209, 0.0},
                                       {-0.02903, 0.06377, -0.03202, 0.00394},
                                       {0.11693, -0.21196, 0.06052, 0.25886}};
    return zenith_chromaticity(m, t, theta_s);
}

double preetham_zenith_y(double t, double theta_s) {
    static constexpr double m[3][4] = {{0.00275, -0.00610, 0.00317, 0.0},
                                       {-0.04214, 0.08970, -0.04153, 0.00516},
                                       {0.15346, -0.26756, 0.06670, 0.26688}};
    return zenith_chromaticity(m, t, theta_s);
}

PreethamSky::PreethamSky(double turbidity, double ground_albedo, const glm::dvec3& sun_direction_enu)
    : turbidity_(turbidity), albedo_(ground_albedo) {
    glm::dvec3 s = sun_direction_enu;
    const double len = std::sqrt(s.x * s.x + s.y * s.y + s.z * s.z);
    s = (std::isfinite(len) && len > 0.0) ? s / len : glm::dvec3(0.0, 0.0, 1.0);
    sun_.direction = s;
    sun_.irradiance = sun_beam_irradiance(turbidity, s, sun_.angular_radius_rad);

    // The model's sun: the true one, or its azimuth on the horizon when it has set.
    model_sun_ = s;
    if (s.z < 0.0) {
        const double h = std::hypot(s.x, s.y);
        model_sun_ = h > 0.0 ? glm::dvec3(s.x / h, s.y / h, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
        const double elevation_deg = std::asin(std::max(s.z, -1.0)) * 180.0 / kPi;
        twilight_ = std::clamp(1.0 + elevation_deg / kTwilightDepthDeg, 0.0, 1.0);
    }
    const double theta_s = std::acos(std::clamp(model_sun_.z, 0.0, 1.0));

    cY_ = preetham_perez_luminance(turbidity);
    cx_ = preetham_perez_x(turbidity);
    cy_ = preetham_perez_y(turbidity);
    zenith_Y_ = std::max(0.0, preetham_zenith_luminance(turbidity, theta_s));
    zenith_x_ = preetham_zenith_x(turbidity, theta_s);
    zenith_y_ = preetham_zenith_y(turbidity, theta_s);
    norm_Y_ = perez(cY_, 1.0, theta_s);
    norm_x_ = perez(cx_, 1.0, theta_s);
    norm_y_ = perez(cy_, 1.0, theta_s);

    // Ground: a Lambertian plane lit by the dome and the sun's beam.
    glm::dvec3 e(0.0);
    for_each_sky_node(HemisphereRule{24, 96}, false, [&](const glm::dvec3& d, double w) {
        const Rgb l = sky_radiance(d);
        e += glm::dvec3(l) * (w * d.z);
    });
    sky_horizontal_ = Rgb(e);
    const Rgb sun_horizontal = sun_.irradiance * static_cast<float>(std::max(0.0, s.z));
    ground_ = (sky_horizontal_ + sun_horizontal) * static_cast<float>(albedo_ / kPi);
}

Rgb PreethamSky::sky_radiance(const glm::dvec3& dir) const {
    const double cos_theta = std::clamp(dir.z, 1e-3, 1.0);
    const double cos_gamma = std::clamp(dir.x * model_sun_.x + dir.y * model_sun_.y + dir.z * model_sun_.z, -1.0, 1.0);
    const double gamma = std::acos(cos_gamma);
    const double Y = zenith_Y_ * perez(cY_, cos_theta, gamma) / norm_Y_ * twilight_;
    const double x = zenith_x_ * perez(cx_, cos_theta, gamma) / norm_x_;
    const double y = zenith_y_ * perez(cy_, cos_theta, gamma) / norm_y_;
    return xyY_to_linear_srgb(x, y, std::max(0.0, Y));
}

Rgb PreethamSky::radiance(const glm::dvec3& dir) const {
    return dir.z > 0.0 ? sky_radiance(dir) : ground_;
}

std::string PreethamSky::describe() const {
    char buf[160];
    std::snprintf(buf, sizeof buf, "clear sky (Preetham 1999), turbidity %.2f, ground albedo %.2f, zenith %.2f kcd/m2",
                  turbidity_, albedo_, zenith_Y_ * twilight_);
    return buf;
}

}  // namespace ts::light
