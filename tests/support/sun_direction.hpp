#pragma once
// A sun direction in east-north-up from azimuth (degrees clockwise from north) and elevation,
// through core/geo's one azimuth convention.
#include <glm/vec3.hpp>

#include "core/geo/azimuth.hpp"
#include "core/util/angles.hpp"

namespace ts::test {

inline glm::dvec3 sun_from(double azimuth_cw_deg, double elevation_deg) {
    return geo::enu_direction(geo::azimuth_cw_from_north_to_phi(azimuth_cw_deg), radians(elevation_deg));
}

}  // namespace ts::test
