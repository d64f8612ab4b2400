#include "core/light/overcast_sky.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/util/angles.hpp"

namespace ts::light {

double overcast_zenith_luminance(double sun_elevation_deg) {
    const double e = std::isfinite(sun_elevation_deg) ? std::min(sun_elevation_deg, 90.0) : 0.0;
    if (e >= 0.0) return 0.123 + 8.6 * std::sin(e * kPi / 180.0);
    // Below the horizon Krochmann's fit has nothing to say: fade its 0.123 kcd/m^2 linearly to 0
    // at -6 deg, as the clear sky does, so day-night sequences end in the dark.
    return 0.123 * std::clamp(1.0 + e / 6.0, 0.0, 1.0);
}

OvercastSky::OvercastSky(double brightness, double ground_albedo, const glm::dvec3& sun_direction_enu)
    : albedo_(ground_albedo) {
    glm::dvec3 s = sun_direction_enu;
    const double len = std::sqrt(s.x * s.x + s.y * s.y + s.z * s.z);
    s = (std::isfinite(len) && len > 0.0) ? s / len : glm::dvec3(0.0, 0.0, 1.0);
    sun_.direction = s;
    sun_.irradiance = Rgb(0.0f);
    zenith_ = brightness * overcast_zenith_luminance(std::asin(std::clamp(s.z, -1.0, 1.0)) * 180.0 / kPi);
}

double OvercastSky::horizontal_illuminance() const {
    // Integral over the upper hemisphere of L_z (1 + 2 cos t)/3 cos t dw = L_z (pi + 4 pi / 3) / 3.
    return 7.0 * kPi / 9.0 * zenith_;
}

Rgb OvercastSky::radiance(const glm::dvec3& dir) const {
    if (dir.z > 0.0) return Rgb(static_cast<float>(zenith_ * (1.0 + 2.0 * std::min(dir.z, 1.0)) / 3.0));
    return Rgb(static_cast<float>(albedo_ * horizontal_illuminance() / kPi));
}

std::string OvercastSky::describe() const {
    char buf[128];
    std::snprintf(buf, sizeof buf, "overcast sky (CIE standard overcast), zenith %.2f kcd/m2, ground albedo %.2f",
                  zenith_, albedo_);
    return buf;
}

}  // namespace ts::light
