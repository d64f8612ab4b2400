// light::SkyTable on the whole sphere (render's water mirror and perspective sky): samples at
// texel centres from phi = -pi and the zenith, as render's table had them, and a lookup at a
// sample's direction returns that sample; on a node grid the first and last rows lie on their
// elevations.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geo/azimuth.hpp"
#include "core/light/sky.hpp"
#include "core/light/sky_table.hpp"
#include "core/util/angles.hpp"

namespace ts::light {
namespace {

TEST(SkyTable, WholeSphereSamplesTexelCentresAsRenderDid) {
    const auto sky = make_sky(SkyOptions{}, geo::enu_direction(geo::azimuth_cw_from_north_to_phi(200.0), radians(30.0)));
    SkyTable table(SkyGrid::whole_sphere(16, 8));
    table.update(*sky);
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 16; ++i) {
            // core/render/sky_table.cpp's former formula.
            const double el = kPi / 2 - kPi * (j + 0.5) / 8;
            const double phi = -kPi + 2 * kPi * (i + 0.5) / 16;
            const glm::dvec3 d{std::cos(el) * std::cos(phi), std::cos(el) * std::sin(phi), std::sin(el)};
            const Rgb want = sky->radiance(d);
            ASSERT_EQ(table.radiance()[std::size_t(j) * 16 + std::size_t(i)], want);
            const Rgb got = table.lookup(glm::vec3(d));
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-4f * std::max(1.0f, want[c]));
        }
}

TEST(SkyTable, ClampsToAtLeastFourByTwo) {
    SkyTable t(SkyGrid::whole_sphere(1, 1));
    EXPECT_EQ(t.width(), 4);
    EXPECT_EQ(t.height(), 2);
}

}  // namespace
}  // namespace ts::light
