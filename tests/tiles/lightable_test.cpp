// The lightable tiles' sun bands and sky turn (core/tiles/lightable_tile.hpp, lightable_sky.hpp);
// the tiles themselves against relief are tests/web/relight_agreement_test.mjs.
#include <gtest/gtest.h>

#include <cmath>

#include "core/light/sky.hpp"
#include "core/render/shading_state.hpp"
#include "core/tiles/lightable_sky.hpp"
#include "core/tiles/lightable_tile.hpp"

namespace ts::tiles {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

TEST(SunBands, MidLatitudeKeepsTheSunsDirectionsWithItsElevations) {
    const int d_count = 128;
    const std::vector<SunBand> bands = sun_bands(45.5, d_count);
    ASSERT_FALSE(bands.empty());
    for (const SunBand& b : bands) {
        const double az = 360.0 * b.direction / d_count;
        // At 45.5 N the sun rises no further north than ~55 deg from north.
        EXPECT_TRUE(az > 45.0 && az < 315.0) << az;
        EXPECT_LE(b.lowest_rad, b.highest_rad);
    }
    // Due south: the noon sun, 21 deg in December to 68 deg in June.
    for (const SunBand& b : bands)
        if (b.direction == d_count / 2) {
            EXPECT_NEAR(b.lowest_rad / kDeg, 90 - 45.5 - 23.44, 0.5);
            EXPECT_NEAR(b.highest_rad / kDeg, 90 - 45.5 + 23.44, 0.5);
        }
}

TEST(SunBands, PolarSummerShinesFromEveryDirection) {
    EXPECT_EQ(sun_bands(80.0, 64).size(), 64u);
    EXPECT_EQ(sun_bands(0.0, 64).size(), 64u);
}

TEST(TurnSkySh, EqualsTheSkyProjectedWithTheSunThere) {
    light::SkyOptions o;
    for (double az : {0.0, 137.0, 200.0, 315.0}) {
        const auto east = light::project_sky_sh(*light::make_sky(o, render::sun_direction({90.0, 20.0})));
        const auto there = light::project_sky_sh(*light::make_sky(o, render::sun_direction({az, 20.0})));
        std::array<light::Rgb, 9> table;
        for (int i = 0; i < 9; ++i) table[std::size_t(i)] = east[std::size_t(i)];
        const auto turned = turn_sky_sh(table, az);
        for (int i = 0; i < 9; ++i)
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(turned[std::size_t(i)][c], there[std::size_t(i)][c], 2e-3 * std::abs(there[0][c]))
                    << "azimuth " << az << " coefficient " << i;
    }
}

}  // namespace
}  // namespace ts::tiles
