#pragma once
// A sun direction in east-north-up from azimuth (degrees clockwise from north) and elevation.
#include <cmath>
#include <glm/vec3.hpp>
#include <numbers>

namespace ts::test {

inline glm::dvec3 sun_from(double azimuth_cw_deg, double elevation_deg) {
    const double phi = (90.0 - azimuth_cw_deg) * std::numbers::pi / 180.0, e = elevation_deg * std::numbers::pi / 180.0;
    return {std::cos(e) * std::cos(phi), std::cos(e) * std::sin(phi), std::sin(e)};
}

}  // namespace ts::test
