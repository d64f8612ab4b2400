#include "core/util/angles.hpp"
#include "core/visibility/sun_visibility.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "core/geo/azimuth.hpp"
#include "core/util/error.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "synthetic_terrain.hpp"

using namespace ts::visibility;
using ts::visibility::testing::make_terrain;
using ts::kPi;
using ts::radians;

namespace {

// Visible fraction of a unit disc above the line y = -x (x = centre height above the line in
// radii) by the midpoint rule over chords: the reference for the closed form.
double disc_fraction_by_chords(double x, int steps) {
    double area = 0;
    for (int i = 0; i < steps; ++i) {
        const double y = -1.0 + (i + 0.5) * 2.0 / steps;
        if (y > -x) area += 2.0 * std::sqrt(1.0 - y * y) * 2.0 / steps;
    }
    return area / kPi;
}

SunVisibilityOptions sun_opts(bool curvature = false, int threads = 2) {
    SunVisibilityOptions o;
    o.curvature = curvature;
    o.threads = threads;
    return o;
}

}  // namespace

TEST(SunDisc, ExactAtTheEdgesAndHalfAtTheCentre) {
    const double r = 0.004654;
    EXPECT_EQ(sun_disc_visible_fraction(0.0, r, r), 1.0);
    EXPECT_EQ(sun_disc_visible_fraction(0.0, -r, r), 0.0);
    EXPECT_EQ(sun_disc_visible_fraction(0.1, 0.1 + 2 * r, r), 1.0);
    EXPECT_EQ(sun_disc_visible_fraction(0.1, 0.1 - 2 * r, r), 0.0);
    EXPECT_NEAR(sun_disc_visible_fraction(0.2, 0.2, r), 0.5, 1e-15);
    // Point sun: a step.
    EXPECT_EQ(sun_disc_visible_fraction(0.0, 1e-9, 0.0), 1.0);
    EXPECT_EQ(sun_disc_visible_fraction(0.0, -1e-9, 0.0), 0.0);
    EXPECT_TRUE(std::isnan(sun_disc_visible_fraction(std::nan(""), 0.1, r)));
}

TEST(SunDisc, MatchesNumericalIntegration) {
    // Midpoint rule with 2e5 chords: its error is dominated by the chord cut at the line and
    // the sqrt ends, < 2e-5 of the disc; the closed form must agree to that.
    const double r = 0.004654;
    double previous = -1;
    for (int i = 0; i <= 100; ++i) {
        const double x = -1.0 + 2.0 * i / 100.0;
        const double f = sun_disc_visible_fraction(0.3, 0.3 + x * r, r);
        EXPECT_NEAR(f, disc_fraction_by_chords(x, 200000), 2e-5) << "x=" << x;
        EXPECT_GE(f, previous) << "monotone in the sun's height, x=" << x;
        previous = f;
    }
}

TEST(SunVisibility, WallCastsShadowOfLengthHOverTanE) {
    // Flat ground (10 m texels) with a north-south wall 100 m high, three texels thick (flat
    // top from column 18 to 20). The sun west of it at elevation e: texels east of it closer
    // than H / tan(e) along the sun's azimuth are in shadow (visible fraction < 0.5). The
    // bilinear surface slopes from the top's east edge to the ground over one texel, below
    // the sun's ray, so the shadow's end must be within one texel (10 m) of the formula,
    // measured across the wall (the sun's ray crosses it at an angle for azimuths other than
    // 270). (A one-texel wall would be a sharp ridge, which marching in 1/4-texel steps, like
    // the reference and the near field, sees up to 1/8 texel off its crest: 12% too low here.)
    const double dx = 10.0, H = 100.0;
    const int wall_col = 20;
    auto t = make_terrain(160, 60, dx, dx, [](double, double) { return 0.0; });
    for (int r = 0; r < 60; ++r)
        for (int c = wall_col - 2; c <= wall_col; ++c) t.z[std::size_t(r) * 160 + c] = float(H);
    for (double az : {270.0, 240.0, 300.0}) {
        // Elevations whose shadow ends between texel centres for every azimuth here (a texel
        // exactly on the edge sees half the disc, and rounding decides its side).
        for (double e : {20.0, 35.0, 55.0}) {
            const std::vector<float> vis = sun_visibility(t.grid, az, e, sun_opts());
            const double across = H / std::tan(radians(e)) * std::abs(std::cos(radians(az - 270.0)));
            for (int r = 20; r < 40; ++r) {  // rows whose rays reach the wall inside the grid
                int last_shadow = -1;
                for (int c = wall_col + 1; c < 160; ++c)
                    if (vis[std::size_t(r) * 160 + c] < 0.5f) last_shadow = c;
                ASSERT_GT(last_shadow, wall_col) << "az " << az << " e " << e;
                const double end_m = (last_shadow - wall_col) * dx;
                EXPECT_NEAR(end_m, across, dx) << "az " << az << " e " << e << " row " << r;
                // Sunlit west of the wall: nothing blocks the sun there.
                for (int c = 0; c < wall_col - 2; ++c) ASSERT_EQ(vis[std::size_t(r) * 160 + c], 1.0f) << c;
            }
        }
    }
}

TEST(SunVisibility, EastWestWallShadowsNorthwardForSouthernSun) {
    // The same along columns (row sweeps): an east-west wall three texels thick (rows 40..42),
    // the sun due south at 30 degrees, shadow north of it over H / tan(e) = 173 m, within one
    // 10 m texel.
    const double dx = 10.0, H = 100.0;
    const int wall_row = 40;
    auto t = make_terrain(30, 50, dx, dx, [](double, double) { return 0.0; });
    for (int r = wall_row; r <= wall_row + 2; ++r)
        for (int c = 0; c < 30; ++c) t.z[std::size_t(r) * 30 + c] = float(H);
    const std::vector<float> vis = sun_visibility(t.grid, 180.0, 30.0, sun_opts());
    for (int c = 0; c < 30; ++c) {
        int last_shadow = -1;
        for (int r = wall_row - 1; r >= 0; --r)
            if (vis[std::size_t(r) * 30 + c] < 0.5f) last_shadow = r;
        ASSERT_GE(last_shadow, 0);
        EXPECT_NEAR((wall_row - last_shadow) * dx, H / std::tan(radians(30.0)), dx) << "col " << c;
    }
}

TEST(SunVisibility, SunBelowTheHorizonGivesZero) {
    // Flat ground with curvature: the horizon is ~0 (the ground falls away), so a sun whose
    // disc lies wholly below 0 is hidden everywhere, and one wholly above is fully visible.
    auto t = make_terrain(50, 40, 30, 30, [](double, double) { return 200.0; });
    for (double az : {0.0, 95.0, 200.0, 333.0}) {
        for (float v : sun_visibility(t.grid, az, -1.0, sun_opts(true))) ASSERT_EQ(v, 0.0f) << az;
        for (float v : sun_visibility(t.grid, az, 1.0, sun_opts(true))) ASSERT_EQ(v, 1.0f) << az;
    }
}

TEST(SunVisibility, OneAzimuthEqualsExactHorizonsPlane) {
    // exact_horizon_in_azimuth runs exact_horizons' per-azimuth code; with the lines split among
    // threads only the association of a texel's two or three line contributions can change, so
    // the tolerance is 1e-6 rad (float rounding of the sums), on square and geographic rows.
    auto t = make_terrain(90, 70, 30, 30, ts::visibility::testing::hills);
    for (bool geographic : {false, true}) {
        if (geographic)
            for (int r = 0; r < 70; ++r)
                t.grid.dx_m[std::size_t(r)] = 60.0 - 15.0 * r / 69.0, t.grid.dy_m[std::size_t(r)] = 92.0;
        HorizonOptions o;
        o.directions = 24;
        o.curvature = true;
        o.threads = 2;
        const HorizonSet set = compute_horizons(t.grid, o);
        for (int threads : {1, 2, 3}) {
            o.threads = threads;
            for (int d = 0; d < 24; ++d) {
                const std::vector<float> one = exact_horizon_in_azimuth(t.grid, azimuth_rad(d, 24), o);
                ASSERT_EQ(one.size(), set.texels());
                for (std::size_t i = 0; i < one.size(); ++i)
                    ASSERT_NEAR(one[i], set.plane(d)[i], 1e-6) << "d=" << d << " i=" << i << " threads=" << threads;
            }
        }
    }
}

TEST(SunVisibility, BandShortcutKeepsTheFractionOfTheFullHorizon) {
    // sun_visibility stops the near-field march once the horizon is known to be outside the
    // disc; the fraction must equal the one from the full exact horizon in that azimuth, to
    // 1e-6 (the band is widened past fast_atan's error, so only float rounding remains).
    auto t = make_terrain(80, 80, 30, 30, ts::visibility::testing::hills);
    HorizonOptions o;
    o.curvature = true;
    o.threads = 2;
    o.exact_near_field_texels = SunVisibilityOptions{}.near_field_texels;
    for (double az : {35.0, 170.0, 261.0}) {
        const std::vector<float> h = exact_horizon_in_azimuth(t.grid, ts::geo::azimuth_cw_from_north_to_phi(az), o);
        for (double e : {2.0, 9.0, 21.0, 45.0}) {
            const std::vector<float> vis = sun_visibility(t.grid, az, e, sun_opts(true));
            int rim = 0;
            for (std::size_t i = 0; i < vis.size(); ++i) {
                const double f = sun_disc_visible_fraction(h[i], radians(e), 0.004654);
                ASSERT_NEAR(vis[i], f, 1e-6) << "az " << az << " e " << e << " i " << i;
                rim += f > 0 && f < 1;
            }
            if (e == 9.0) {
                EXPECT_GT(rim, 0) << "some texels must see part of the disc, az " << az;
            }
        }
    }
}

TEST(SunVisibility, AgreesWithRaymarchedHorizonOnHills) {
    // The sun's shadow mask (fraction < 0.5) from the exact sweep against the fraction from the
    // reference raymarch horizon in the same azimuth (D = 8 covers azimuth 45 = phi 45 deg):
    // the exact method's horizon is within ~0.5 degree of the reference (docs/visibility.md),
    // so masks may differ only on the shadow's rim: < 3% of the texels.
    auto t = make_terrain(96, 96, 30, 30, ts::visibility::testing::hills);
    HorizonOptions o;
    o.directions = 8;
    o.method = HorizonMethod::raymarch;
    o.curvature = true;
    o.threads = 2;
    const HorizonSet ref = compute_horizons(t.grid, o);
    const int d = 1;  // phi = 45 deg = azimuth 45 (north-east)
    const double az = user_azimuth_deg(d, 8);
    for (double e : {5.0, 12.0, 25.0}) {
        const std::vector<float> vis = sun_visibility(t.grid, az, e, sun_opts(true));
        int differ = 0, shadowed = 0;
        for (std::size_t i = 0; i < vis.size(); ++i) {
            const double f_ref = sun_disc_visible_fraction(ref.plane(d)[i], radians(e), 0.004654);
            differ += (vis[i] < 0.5f) != (f_ref < 0.5);
            shadowed += f_ref < 0.5;
        }
        EXPECT_GT(shadowed, 0) << "e=" << e << ": the test needs shadows";
        EXPECT_LT(differ, int(0.03 * double(vis.size()))) << "e=" << e;
    }
}

TEST(SunVisibility, VoidsAreNaNAndDoNotCast) {
    auto t = make_terrain(40, 40, 30, 30, [](double, double) { return 100.0; });
    // A tall block inside the void region: it must not cast (voids have no surface, and the
    // block is replaced by NaN).
    for (int r = 15; r < 22; ++r)
        for (int c = 10; c < 18; ++c) t.z[std::size_t(r) * 40 + c] = std::numeric_limits<float>::quiet_NaN();
    const std::vector<float> vis = sun_visibility(t.grid, 270.0, 10.0, sun_opts());
    for (int r = 0; r < 40; ++r)
        for (int c = 0; c < 40; ++c) {
            const float v = vis[std::size_t(r) * 40 + c];
            if (r >= 15 && r < 22 && c >= 10 && c < 18)
                ASSERT_TRUE(std::isnan(v));
            else
                ASSERT_EQ(v, 1.0f) << c << "," << r;
        }
}

TEST(SunVisibility, WindowEqualsWholeGrid) {
    auto t = make_terrain(64, 48, 30, 30, ts::visibility::testing::hills);
    const std::vector<float> whole = sun_visibility(t.grid, 130.0, 15.0, sun_opts(true));
    SunVisibilityOptions o = sun_opts(true);
    o.window = {20, 10, 30, 25};
    const std::vector<float> part = sun_visibility(t.grid, 130.0, 15.0, o);
    ASSERT_EQ(part.size(), 30u * 25u);
    for (int r = 0; r < 25; ++r)
        for (int c = 0; c < 30; ++c)
            ASSERT_NEAR(part[std::size_t(r) * 30 + c], whole[std::size_t(r + 10) * 64 + c + 20], 1e-5) << c << "," << r;
}

TEST(SunVisibility, RejectsBadInput) {
    auto t = make_terrain(8, 8, 30, 30, [](double, double) { return 0.0; });
    EXPECT_THROW(sun_visibility(t.grid, 10.0, 95.0), ts::InputError);
    EXPECT_THROW(sun_visibility(t.grid, std::nan(""), 10.0), ts::InputError);
    SunVisibilityOptions o;
    o.window = {4, 4, 8, 8};
    EXPECT_THROW(sun_visibility(t.grid, 10.0, 10.0, o), ts::InputError);
    ts::terrain::HeightGrid empty;
    EXPECT_THROW(sun_visibility(empty, 10.0, 10.0), ts::InputError);
}
