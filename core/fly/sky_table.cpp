#include "core/fly/sky_table.hpp"

#include <cmath>

#include "core/util/angles.hpp"

namespace ts::fly {

FlySkyTable make_sky_table(const light::Sky& sky, int azimuths, int elevations) {
    FlySkyTable t;
    t.azimuths = azimuths, t.elevations = elevations;
    t.rgb.resize(std::size_t(azimuths) * std::size_t(elevations));
    for (int e = 0; e < elevations; ++e) {
        const double el = t.lowest_rad + (t.highest_rad - t.lowest_rad) * double(e) / double(elevations - 1);
        for (int a = 0; a < azimuths; ++a) {
            const double az = 2.0 * kPi * double(a) / double(azimuths);
            // Below the horizon the model gives the ground's light; the table keeps the sky's
            // horizon colour there instead, which is what a ray over the curved Earth meets.
            const double sample_el = std::max(el, 0.002);
            const glm::dvec3 dir{std::cos(sample_el) * std::cos(az), std::cos(sample_el) * std::sin(az),
                                 std::sin(sample_el)};
            const light::Rgb l = sky.radiance(dir);
            t.rgb[std::size_t(e) * std::size_t(azimuths) + std::size_t(a)] = glm::vec4(l, 1.0f);
        }
    }
    return t;
}

glm::vec3 sun_disc_radiance(const light::SunDisc& sun) {
    const double r = sun.angular_radius_rad;
    const double solid_angle = 2.0 * kPi * (1.0 - std::cos(r));
    return sun.irradiance / float(solid_angle);
}

}  // namespace ts::fly
