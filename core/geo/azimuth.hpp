#pragma once
// The one place where user-facing azimuths become internal angles (docs/architecture.md):
// users (flags, sun positions, outputs) speak degrees clockwise from north, as gdaldem does;
// the code uses phi in radians counter-clockwise from +x = east, in the ENU frame.
#include <cmath>

#include <glm/vec3.hpp>

#include "core/util/angles.hpp"

namespace ts::geo {

// 0 (north) -> pi/2, 90 (east) -> 0, 180 (south) -> -pi/2, 270 (west) -> -pi (== pi).
inline double azimuth_cw_from_north_to_phi(double azimuth_deg) {
    return kPi / 2.0 - radians(azimuth_deg);
}

// The inverse, in [0, 360).
inline double phi_to_azimuth_cw_from_north(double phi_rad) {
    double az = 90.0 - degrees(phi_rad);
    az = std::fmod(az, 360.0);
    return az < 0 ? az + 360.0 : az;
}

// Unit vector in ENU towards a direction given by internal phi and elevation (radians above
// the horizontal).
inline glm::dvec3 enu_direction(double phi_rad, double elevation_rad) {
    const double c = std::cos(elevation_rad);
    return {c * std::cos(phi_rad), c * std::sin(phi_rad), std::sin(elevation_rad)};
}

}  // namespace ts::geo
