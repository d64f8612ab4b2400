#pragma once
// The sky as the flythrough's shaders read it: the sky model's radiance (the sun's disc apart)
// in a light::SkyTable (core/light/sky_table.hpp), for the background and for aerial perspective
// (the horizon radiance in each ray's azimuth). Its grid is what gpu/fly/fly_frame.glsl's
// sky_radiance expects: nodes, phi from 0 (east) counter-clockwise, elevation from a little below
// the horizon (the curvature shows the sky there; it holds the horizon's radiance) to the zenith.
#include <vector>

#include <glm/vec4.hpp>

#include "core/light/sky.hpp"
#include "core/light/sky_table.hpp"

namespace ts::fly {

inline constexpr double kSkyLowestRad = -0.1;
inline constexpr double kSkyHighestRad = 1.5707963267948966;

light::SkyGrid fly_sky_grid(int azimuths = 96, int elevations = 64);

// The table as the shaders' storage buffer: one vec4 a sample (rgb, w = 1 unused).
std::vector<glm::vec4> sky_buffer(const light::SkyTable& table);

// Radiance inside the sun's disc: its irradiance over the disc's solid angle.
glm::vec3 sun_disc_radiance(const light::SunDisc& sun);

}  // namespace ts::fly
