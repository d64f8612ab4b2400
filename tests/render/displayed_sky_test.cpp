// The displayed sky keeps the sky model's colour: the physical clear sky's radiance over the
// whole upper hemisphere, exposed automatically and encoded to 8 bits as every picture is
// (core/render/tone_map.hpp), decoded again, has the model's CIE xy within 0.02 wherever no
// channel is clipped, for the sun from the horizon to 70 degrees. A tone curve applied to each
// channel on its own fails this by up to ~0.1 at a low sun (docs/rendering.md, "Output and tone
// mapping"); scripts/display_hue.py measures the same on rendered views.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include "core/light/physical_sky.hpp"
#include "core/light/sky_color.hpp"
#include "core/raster/srgb.hpp"
#include "core/render/tone_map.hpp"
#include "core/util/angles.hpp"

namespace ts::render {
namespace {

glm::dvec3 sky_direction(double elevation_deg, double azimuth_deg) {
    const double e = elevation_deg * kPi / 180.0, a = azimuth_deg * kPi / 180.0;
    return {std::cos(e) * std::sin(a), std::cos(e) * std::cos(a), std::sin(e)};
}

TEST(DisplayedSky, KeepsTheModelsChromaticityFromTheHorizonTo70Degrees) {
    for (const double sun_elevation : {0.0, 2.0, 5.0, 10.0, 20.0, 40.0, 70.0}) {
        const light::PhysicalSky sky(3.0, 0.2, sky_direction(sun_elevation, 270.0));
        std::vector<glm::vec3> px;
        for (double el = 0.5; el < 90.0; el += 1.5)
            for (double az = 0.0; az < 360.0; az += 3.0) {
                const light::Rgb c = sky.radiance(sky_direction(el, az));
                px.emplace_back(float(c.r), float(c.g), float(c.b));
            }
        const double scale = exposure_scale(Exposure{}, log_average_luminance(px.data(), px.size()));
        const std::vector<std::uint8_t> codes = tone_map_to_srgb8(px.data(), px.size(), scale);
        double worst = 0;
        std::size_t compared = 0, dark = 0;
        for (std::size_t i = 0; i < px.size(); ++i) {
            const std::uint8_t* c = &codes[3 * i];
            if (std::max({c[0], c[1], c[2]}) == 255) continue;  // clipped
            // Below code 16 a channel's rounding alone moves xy by up to ~0.02.
            if (std::min({c[0], c[1], c[2]}) < 16) {
                ++dark;
                continue;
            }
            light::Rgb shown{};
            shown.r = raster::srgb_eotf(float(c[0]) / 255.0f);
            shown.g = raster::srgb_eotf(float(c[1]) / 255.0f);
            shown.b = raster::srgb_eotf(float(c[2]) / 255.0f);
            const light::Chromaticity a = light::chromaticity_of(shown);
            const light::Chromaticity b = light::chromaticity_of({px[i].x, px[i].y, px[i].z});
            worst = std::max(worst, std::hypot(a.x - b.x, a.y - b.y));
            ++compared;
        }
        std::printf("sun %4.1f deg: %zu sky pixels compared, %zu dark, %zu clipped; xy off by at most %.4f\n",
                    sun_elevation, compared, dark, px.size() - compared - dark, worst);
        EXPECT_GT(compared, px.size() * 9 / 10) << sun_elevation;
        EXPECT_LT(worst, 0.02) << sun_elevation;
    }
}

}  // namespace
}  // namespace ts::render
