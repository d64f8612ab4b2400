// The flythrough's sky table is the one light::SkyTable on fly's grid: every sample and every
// lookup the shaders make are those of the table fly had before (its own formula and the GLSL
// bilinear lookup, both copied here as the reference).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/vec4.hpp>

#include "core/fly/fly_sky.hpp"
#include "core/geo/azimuth.hpp"
#include "core/light/sky.hpp"
#include "core/light/sky_table.hpp"
#include "core/util/angles.hpp"

namespace ts::fly {
namespace {

// fly's former make_sky_table: nodes over [0, 2 pi) and [-0.1, pi / 2], sampled no lower than 0.002.
std::vector<glm::vec4> former_table(const light::Sky& sky, int azimuths, int elevations) {
    std::vector<glm::vec4> rgb(std::size_t(azimuths) * std::size_t(elevations));
    const double lowest = -0.1, highest = 1.5707963267948966;
    for (int e = 0; e < elevations; ++e) {
        const double el = lowest + (highest - lowest) * double(e) / double(elevations - 1);
        for (int a = 0; a < azimuths; ++a) {
            const double az = 2.0 * kPi * double(a) / double(azimuths);
            const double sample_el = std::max(el, 0.002);
            const glm::dvec3 dir{std::cos(sample_el) * std::cos(az), std::cos(sample_el) * std::sin(az), std::sin(sample_el)};
            rgb[std::size_t(e) * std::size_t(azimuths) + std::size_t(a)] = glm::vec4(sky.radiance(dir), 1.0f);
        }
    }
    return rgb;
}

// gpu/fly/fly_frame.glsl's sky_radiance on the former table.
glm::vec3 former_lookup(const std::vector<glm::vec4>& sky, int na, int ne, glm::vec3 dir) {
    const float lowest = float(-0.1), highest = float(1.5707963267948966);
    float az = std::atan2(dir.y, dir.x);
    if (az < 0.0f) az += 6.283185307179586f;
    const float el = std::asin(std::clamp(dir.z, -1.0f, 1.0f));
    const float u = az / 6.283185307179586f * float(na);
    float v = (el - lowest) / (highest - lowest) * float(ne - 1);
    v = std::clamp(v, 0.0f, float(ne - 1));
    const int a0 = int(std::floor(u)) % na, a1 = (a0 + 1) % na;
    const int e0 = std::min(int(std::floor(v)), ne - 2), e1 = e0 + 1;
    const float fu = u - std::floor(u), fv = v - float(e0);
    auto at = [&](int e, int a) { return glm::vec3(sky[std::size_t(e) * std::size_t(na) + std::size_t(a)]); };
    const glm::vec3 top = at(e0, a0) * (1 - fu) + at(e0, a1) * fu;
    const glm::vec3 bottom = at(e1, a0) * (1 - fu) + at(e1, a1) * fu;
    return top * (1 - fv) + bottom * fv;
}

TEST(FlySky, SamplesAndLookupsAreThoseOfTheFormerFlyTable) {
    // A low sun in the south-east: the sky varies strongly in azimuth and elevation.
    const glm::dvec3 sun = geo::enu_direction(geo::azimuth_cw_from_north_to_phi(135.0), radians(12.0));
    const auto sky = light::make_sky(light::SkyOptions{}, sun);
    light::SkyTable table(fly_sky_grid());
    table.update(*sky);
    const std::vector<glm::vec4> former = former_table(*sky, 96, 64);
    const std::vector<glm::vec4> now = sky_buffer(table);
    ASSERT_EQ(now.size(), former.size());
    for (std::size_t k = 0; k < now.size(); ++k) ASSERT_EQ(now[k], former[k]) << "sample " << k;

    // The uniform the shaders read: azimuths, elevations, lowest and highest elevation.
    EXPECT_EQ(table.grid().azimuths, 96);
    EXPECT_EQ(table.grid().elevations, 64);
    EXPECT_EQ(float(table.grid().first_el), float(-0.1));
    EXPECT_EQ(float(table.grid().last_el), float(1.5707963267948966));

    // SkyTable::lookup on fly's grid is the shaders' lookup, over the sphere (below the lowest
    // row, across the azimuth seam at east, at the zenith) to float rounding.
    int checked = 0;
    for (int i = 0; i < 73; ++i)
        for (int j = 0; j < 37; ++j) {
            const double phi = -kPi + 2 * kPi * (i + 0.37) / 73, el = -0.4 + (kPi / 2 + 0.4) * j / 36;
            const glm::vec3 dir(geo::enu_direction(phi, el));
            const glm::vec3 want = former_lookup(former, 96, 64, dir), got = table.lookup(dir);
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(got[c], want[c], 1e-5f * std::max(1.0f, std::abs(want[c])));
            ++checked;
        }
    EXPECT_EQ(checked, 73 * 37);
}

}  // namespace
}  // namespace ts::fly
