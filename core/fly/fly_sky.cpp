#include "core/fly/fly_sky.hpp"

#include <cmath>

#include "core/util/angles.hpp"

namespace ts::fly {

light::SkyGrid fly_sky_grid(int azimuths, int elevations) {
    light::SkyGrid g;
    g.azimuths = azimuths, g.elevations = elevations;
    g.phi_begin = 0.0;
    g.first_el = kSkyLowestRad, g.last_el = kSkyHighestRad;
    g.texel_centres = false;
    // Below the horizon the model gives the ground's light; the table keeps the sky's horizon
    // colour there instead, which is what a ray over the curved Earth meets.
    g.lowest_sampled_el = 0.002;
    return g;
}

std::vector<glm::vec4> sky_buffer(const light::SkyTable& table) {
    std::vector<glm::vec4> out;
    out.reserve(table.radiance().size());
    for (const light::Rgb& l : table.radiance()) out.emplace_back(l, 1.0f);
    return out;
}

glm::vec3 sun_disc_radiance(const light::SunDisc& sun) {
    const double r = sun.angular_radius_rad;
    const double solid_angle = 2.0 * kPi * (1.0 - std::cos(r));
    return sun.disc_irradiance() / float(solid_angle);
}

}  // namespace ts::fly
