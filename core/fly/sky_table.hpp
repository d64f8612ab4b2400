#pragma once
// The sky as the flythrough's shaders read it: the sky model's radiance (core/light/sky.hpp,
// the sun's disc apart) sampled on an azimuth x elevation grid, for the background and for
// aerial perspective (the horizon radiance in each ray's azimuth). Azimuth counter-clockwise
// from east over [0, 2 pi), `azimuths` columns; elevation from `lowest_rad` (below the
// horizon: the curvature shows the sky a little below it) to the zenith, `elevations` rows;
// bilinear in between (gpu/fly/fly_frame.glsl).
#include <vector>

#include <glm/vec4.hpp>

#include "core/light/sky.hpp"

namespace ts::fly {

struct FlySkyTable {
    int azimuths = 96, elevations = 64;
    double lowest_rad = -0.1, highest_rad = 1.5707963267948966;
    std::vector<glm::vec4> rgb;  // [elevation][azimuth], w unused
};

FlySkyTable make_sky_table(const light::Sky& sky, int azimuths = 96, int elevations = 64);

// Radiance inside the sun's disc: its irradiance over the disc's solid angle.
glm::vec3 sun_disc_radiance(const light::SunDisc& sun);

}  // namespace ts::fly
