#include "core/solar/cie_clear_sky.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/util/angles.hpp"

namespace ts::solar {

double cie_clear_sky_indicatrix(double cos_chi) {
    cos_chi = std::clamp(cos_chi, -1.0, 1.0);
    const double chi = std::acos(cos_chi);
    return 1 + 10 * (std::exp(-3 * chi) - std::exp(-3 * kPi / 2)) + 0.45 * cos_chi * cos_chi;
}

double cie_clear_sky_gradation(double cos_zenith) {
    // exp(-0.32 / cos Z) vanishes at the horizon; below it the horizon's value.
    return cos_zenith > 1e-9 ? 1 - std::exp(-0.32 / cos_zenith) : 1.0;
}

double cie_clear_sky_radiance(const glm::dvec3& sun, const glm::dvec3& w) {
    return cie_clear_sky_indicatrix(glm::dot(sun, w)) * cie_clear_sky_gradation(w.z);
}

double cie_clear_sky_horizontal_integral(double sun_elevation_rad) {
    const glm::dvec3 sun(std::cos(sun_elevation_rad), 0.0, std::sin(sun_elevation_rad));
    constexpr int kAzimuths = 720, kElevations = 360;
    const double de = (kPi / 2) / kElevations, dphi = 2 * kPi / kAzimuths;
    double sum = 0;
    for (int i = 0; i < kAzimuths; ++i) {
        const double phi = (i + 0.5) * dphi;
        for (int k = 0; k < kElevations; ++k) {
            const double e = (k + 0.5) * de;
            const glm::dvec3 w(std::cos(e) * std::cos(phi), std::cos(e) * std::sin(phi), std::sin(e));
            sum += cie_clear_sky_radiance(sun, w) * w.z * std::cos(e);
        }
    }
    return sum * de * dphi;
}

}  // namespace ts::solar
