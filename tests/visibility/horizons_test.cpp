#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/sky_integrals.hpp"
#include "synthetic_terrain.hpp"

using namespace ts::visibility;
using ts::visibility::testing::make_terrain;
using ts::degrees;
using ts::kPi;
constexpr HorizonMethod kMethods[] = {HorizonMethod::exact, HorizonMethod::pyramid, HorizonMethod::raymarch};

HorizonOptions opts(HorizonMethod m, int d, bool curvature = false) {
    HorizonOptions o;
    o.method = m;
    o.directions = d;
    o.curvature = curvature;
    o.threads = 2;
    return o;
}

double rad2deg(double r) {
    return degrees(r);
}

// Comparisons skip the outermost texel ring: a receiver on the grid's edge facing out has no
// terrain in front of it, and whether a sweep line half a texel inside counts is a convention.
double rms_interior_deg(const HorizonSet& a, const HorizonSet& b) {
    double se = 0;
    long n = 0;
    for (int d = 0; d < a.directions; ++d)
        for (int r = 1; r + 1 < a.height; ++r)
            for (int c = 1; c + 1 < a.width; ++c) se += std::pow(rad2deg(a.at(d, c, r) - b.at(d, c, r)), 2), ++n;
    return std::sqrt(se / double(n));
}

double svf_rmse_interior(const HorizonSet& a, const HorizonSet& b) {
    const auto sa = svf_raster(a), sb = svf_raster(b);
    double se = 0;
    long n = 0;
    for (int r = 1; r + 1 < a.height; ++r)
        for (int c = 1; c + 1 < a.width; ++c)
            se += std::pow(sa[std::size_t(r) * a.width + c] - sb[std::size_t(r) * a.width + c], 2), ++n;
    return std::sqrt(se / double(n));
}

TEST(Horizons, FlatGroundHasZeroHorizonAndFullSky) {
    auto t = make_terrain(40, 30, 30, 30, [](double, double) { return 500.0; });
    for (HorizonMethod m : kMethods) {
        const HorizonSet set = compute_horizons(t.grid, opts(m, 16));
        for (float a : set.angle) ASSERT_EQ(a, 0.0f) << method_name(m);
        for (float v : svf_raster(set)) ASSERT_EQ(v, 1.0f) << method_name(m);
    }
}

TEST(Horizons, SquarePitBottomMatchesClosedForm) {
    // Inverted square pyramid z = k (|x| + |y|): the bilinear surface of the grid is exactly
    // this surface (its creases lie on texel lines), and from the bottom the elevation is the
    // same at every distance, so sigma(phi) = atan(k (|cos phi| + |sin phi|)) exactly. Tested
    // on square and non-square cells (dx != dy, as on a geographic grid).
    const double k = 0.5;
    for (auto [dx, dy] : {std::pair{30.0, 30.0}, std::pair{20.0, 55.0}}) {
        auto t = make_terrain(61, 61, dx, dy, [&](double x, double y) { return k * (std::abs(x) + std::abs(y)); });
        for (HorizonMethod m : kMethods) {
            const HorizonSet set = compute_horizons(t.grid, opts(m, 32));
            for (int d = 0; d < 32; ++d) {
                const double phi = azimuth_rad(d, 32);
                const double expected = std::atan(k * (std::abs(std::cos(phi)) + std::abs(std::sin(phi))));
                // raymarch: float rounding only. exact interpolates between sweep lines passing
                // up to 1/2 texel beside the apex, on the walls, whose far-side view is lower by
                // ~ k / distance to the rim: 1 degree. pyramid: its coarse levels average across
                // the crease, which raises a convex pit by up to half a texel: 5 degrees.
                const double tol = m == HorizonMethod::exact ? 1.0 : m == HorizonMethod::pyramid ? 5.0 : 0.01;
                EXPECT_NEAR(rad2deg(set.at(d, 30, 30)), rad2deg(expected), tol)
                    << method_name(m) << " d=" << d << " dx=" << dx;
            }
        }
    }
}

TEST(Horizons, SquarePitSvfClosedForm) {
    // svf of the square pit's bottom: with a = 1 + k^2, b = k^2 (cos^2 sigma = 1/(a + b sin 2 phi)),
    // svf = (2 / pi) (pi/2 - atan(b / sqrt(a^2 - b^2))) / sqrt(a^2 - b^2).
    const double k = 0.5, a = 1 + k * k, b = k * k, q = std::sqrt(a * a - b * b);
    const double svf_exact = 2.0 / kPi * (kPi / 2 - std::atan(b / q)) / q;
    auto t = make_terrain(41, 41, 30, 30, [&](double x, double y) { return k * (std::abs(x) + std::abs(y)); });
    double prev = 1;
    for (int d : {8, 16, 32, 64}) {
        HorizonOptions o = opts(HorizonMethod::raymarch, d);
        o.window = {20, 20, 1, 1};
        const HorizonSet set = compute_horizons(t.grid, o);
        const double err = std::abs(sky_view_factor(set.angle.data(), d, 1) - svf_exact);
        // Linear wedges converge as 1/D^2 (the kinks of sigma sit on computed azimuths).
        EXPECT_LT(err, 2.0 / (d * d)) << d;
        EXPECT_LE(err, prev) << d;
        prev = err;
    }
}

TEST(Horizons, VValleyFloorMatchesClosedFormSvf) {
    // Valley running north-south, walls at slope alpha: svf on the floor = cos(alpha).
    const double alpha = 0.6;
    auto t = make_terrain(101, 101, 30, 30, [&](double x, double) { return std::tan(alpha) * std::abs(x); });
    for (HorizonMethod m : {HorizonMethod::exact, HorizonMethod::raymarch}) {
        HorizonOptions o = opts(m, 64);
        o.window = {50, 40, 1, 21};  // floor texels, away from the valley's ends
        const HorizonSet set = compute_horizons(t.grid, o);
        for (int r = 0; r < set.height; ++r) {
            const double svf = sky_view_factor(&set.angle[std::size_t(r)], 64, set.texels());
            // raymarch: 64 azimuths with linear wedges are within 1e-4 of the closed form; the
            // walls end 50 texels out, which lowers the far-side horizon by up to ~0.3 degree.
            // exact: sweep lines pass 1/2 texel off the floor, on the wall: 0.01.
            EXPECT_NEAR(svf, std::cos(alpha), m == HorizonMethod::raymarch ? 3e-3 : 1e-2) << method_name(m);
        }
    }
}

TEST(Horizons, ExactAgreesWithRaymarchOnHills) {
    // Rough synthetic hills (slopes up to ~45 degrees, 11-texel wavelengths): exact differs from
    // the reference only by interpolating between sweep lines half a texel beside the receiver.
    auto t = make_terrain(90, 80, 30, 30, ts::visibility::testing::hills);
    const HorizonSet ref = compute_horizons(t.grid, opts(HorizonMethod::raymarch, 32, true));
    const HorizonSet ex = compute_horizons(t.grid, opts(HorizonMethod::exact, 32, true));
    const double rms1 = rms_interior_deg(ref, ex);
    // ~1 degree rms here (real DEMs are smoother at their texel scale: docs/visibility.md);
    // a broken sweep or a wrong direction gives tens of degrees.
    EXPECT_LT(rms1, 1.5);
    EXPECT_LT(svf_rmse_interior(ref, ex), 5e-3);
    // Two lines per texel halve the interpolation distance: the error must drop (measured to
    // 0.81 of the one-line RMS here, 0.75 five texels in from the edges).
    HorizonOptions o = opts(HorizonMethod::exact, 32, true);
    o.exact_lines_per_texel = 2;
    EXPECT_LT(rms_interior_deg(ref, compute_horizons(t.grid, o)), 0.85 * rms1);
}

TEST(Horizons, PyramidIsCloseToRaymarchOnHills) {
    auto t = make_terrain(90, 80, 30, 30, ts::visibility::testing::hills);
    const HorizonSet ref = compute_horizons(t.grid, opts(HorizonMethod::raymarch, 16, true));
    const HorizonSet py = compute_horizons(t.grid, opts(HorizonMethod::pyramid, 16, true));
    // The approximate method: a few hundredths of svf rms on these hills (averaged far field).
    EXPECT_LT(svf_rmse_interior(ref, py), 0.03);
}

TEST(Horizons, CurvatureLowersDistantWall) {
    // Flat ground with a 1000 m wall 50 km east of the receiver: tan(sigma) = H/L - L/(2 R_eff).
    const int w = 1101;
    const double dx = 50;
    auto t = make_terrain(w, 3, dx, dx, [&](double x, double) { return x >= 24990.0 ? 1000.0 : 0.0; });
    for (HorizonMethod m : {HorizonMethod::exact, HorizonMethod::raymarch}) {
        HorizonOptions o = opts(m, 4, true);
        o.window = {50, 1, 1, 1};              // receiver at x = -25000 m
        const double dist = (1050 - 50) * dx;  // the first wall texel is col 1050
        const double flat = std::atan(1000.0 / dist);
        const double curved = std::atan(1000.0 / dist - dist / (2 * kEffectiveEarthRadiusM));
        const float with = compute_horizons(t.grid, o).at(0, 0, 0);
        o.curvature = false;
        const float without = compute_horizons(t.grid, o).at(0, 0, 0);
        // The bilinear ramp in front of the wall's first texel raises the horizon by < 1/1000 of
        // it; 1e-4 rad is far below the 3.3e-3 rad the curvature removes.
        EXPECT_NEAR(without, flat, 1e-4) << method_name(m);
        EXPECT_NEAR(with, curved, 1e-4) << method_name(m);
    }
}

TEST(Horizons, VoidsNeitherCastNorReceive) {
    // Flat ground with a void patch: void receivers are NaN, every other texel still sees a
    // horizon of 0 (a void read as a very low or very high height would show up at once).
    auto t = make_terrain(40, 40, 30, 30, [](double, double) { return 100.0; });
    for (int r = 15; r < 22; ++r)
        for (int c = 10; c < 18; ++c) t.z[std::size_t(r) * 40 + c] = std::numeric_limits<float>::quiet_NaN();
    for (HorizonMethod m : kMethods) {
        const HorizonSet set = compute_horizons(t.grid, opts(m, 16));
        for (int r = 0; r < 40; ++r)
            for (int c = 0; c < 40; ++c)
                for (int d = 0; d < 16; ++d) {
                    const bool is_void = r >= 15 && r < 22 && c >= 10 && c < 18;
                    if (is_void)
                        ASSERT_TRUE(std::isnan(set.at(d, c, r)));
                    else
                        ASSERT_NEAR(set.at(d, c, r), 0.0f, 1e-5) << method_name(m) << " " << c << "," << r;
                }
    }
}

TEST(Horizons, ExactEdgeReceiversTakeNoFarFieldFromTheNextLine) {
    // On square texels the sweep lines of the diagonal azimuths pass through texel centres (up
    // to rounding). A receiver on the grid's edge facing out along a diagonal lies on its own
    // line, which starts at it: no far field, and the next line inside, one spacing away, has
    // tent weight 0 there but for rounding. So without the near field the horizon is 0, and a
    // receiver within one texel of the edge sees only terrain its near field marches over, the
    // same for any near field of 2 texels or more (its own line has nothing 2 texels behind;
    // the next line has, and must not count).
    auto t = make_terrain(96, 72, 30, 30, ts::visibility::testing::hills);
    const int w = t.grid.width, h = t.grid.height;
    for (int lpt : {1, 2}) {
        HorizonOptions o = opts(HorizonMethod::exact, 32, true);
        o.exact_lines_per_texel = lpt;
        o.exact_near_field_texels = 0;
        const HorizonSet sweep_only = compute_horizons(t.grid, o);
        o.exact_near_field_texels = 2;
        const HorizonSet near2 = compute_horizons(t.grid, o);
        o.exact_near_field_texels = 4;
        const HorizonSet near4 = compute_horizons(t.grid, o);
        for (int d : {4, 12, 20, 28}) {  // 45, 135, 225, 315 degrees
            const double phi = azimuth_rad(d, 32);
            const bool north = std::sin(phi) > 0, east = std::cos(phi) > 0;  // north is -row
            for (int r = 0; r < h; ++r)
                for (int c = 0; c < w; ++c) {
                    const int rows_in = north ? r : h - 1 - r, cols_in = east ? w - 1 - c : c;
                    const int depth = std::min(rows_in, cols_in);  // texels from an edge it faces
                    if (depth > 1) continue;
                    if (depth == 0) {
                        ASSERT_EQ(sweep_only.at(d, c, r), 0.0f)
                            << "lines " << lpt << " d " << d << " at " << c << "," << r;
                    }
                    ASSERT_EQ(near2.at(d, c, r), near4.at(d, c, r))
                        << "lines " << lpt << " d " << d << " at " << c << "," << r;
                }
        }
    }
}

TEST(Horizons, VoidHoleDoesNotHideMountainBehindIt) {
    // A ridge beyond a void still casts its horizon across the void.
    auto t = make_terrain(60, 5, 30, 30, [](double x, double) { return x > 500 ? 800.0 : 0.0; });
    for (int r = 0; r < 5; ++r)
        for (int c = 20; c < 40; ++c) t.z[std::size_t(r) * 60 + c] = std::numeric_limits<float>::quiet_NaN();
    for (HorizonMethod m : {HorizonMethod::exact, HorizonMethod::raymarch}) {
        HorizonOptions o = opts(m, 4);
        o.window = {5, 2, 1, 1};
        EXPECT_GT(compute_horizons(t.grid, o).at(0, 0, 0), 0.3f) << method_name(m);
    }
}

TEST(Horizons, TilesEqualWholeGrid) {
    // Receivers in 4 tiles of a 64x48 grid, blockers from the whole grid: identical to the
    // whole-grid result, checked at every texel including the tile corners.
    auto t = make_terrain(64, 48, 30, 30, ts::visibility::testing::hills);
    for (HorizonMethod m : kMethods) {
        const HorizonSet whole = compute_horizons(t.grid, opts(m, 16, true));
        for (auto [c0, r0] : {std::pair{0, 0}, std::pair{32, 0}, std::pair{0, 24}, std::pair{32, 24}}) {
            HorizonOptions o = opts(m, 16, true);
            o.window = {c0, r0, 32, 24};
            const HorizonSet tile = compute_horizons(t.grid, o);
            for (int d = 0; d < 16; ++d)
                for (int r = 0; r < 24; ++r)
                    for (int c = 0; c < 32; ++c)
                        ASSERT_FLOAT_EQ(tile.at(d, c, r), whole.at(d, c0 + c, r0 + r))
                            << method_name(m) << " d=" << d << " at " << c0 + c << "," << r0 + r;
        }
    }
}

TEST(Horizons, GeographicRowsAgreeAcrossMethods) {
    // East-west spacing varying by row like a geographic grid at high latitude (60 -> 45 m):
    // exact and raymarch follow the same constant-azimuth lines, so they still agree.
    auto t = make_terrain(80, 80, 30, 30, ts::visibility::testing::hills);
    for (int r = 0; r < 80; ++r)
        t.grid.dx_m[std::size_t(r)] = 60.0 - 15.0 * r / 79.0, t.grid.dy_m[std::size_t(r)] = 92.0;
    const HorizonSet ref = compute_horizons(t.grid, opts(HorizonMethod::raymarch, 16, true));
    const HorizonSet ex = compute_horizons(t.grid, opts(HorizonMethod::exact, 16, true));
    EXPECT_LT(rms_interior_deg(ref, ex), 0.8);
}

TEST(Horizons, RejectsBadOptions) {
    auto t = make_terrain(8, 8, 30, 30, [](double, double) { return 0.0; });
    HorizonOptions o = opts(HorizonMethod::exact, 0);
    EXPECT_THROW(compute_horizons(t.grid, o), ts::InputError);
    o.directions = 8;
    o.window = {4, 4, 8, 8};
    EXPECT_THROW(compute_horizons(t.grid, o), ts::InputError);
    o = opts(HorizonMethod::pyramid, 8);
    o.pyramid_schedule = "nonsense";
    EXPECT_THROW(compute_horizons(t.grid, o), ts::InputError);
}
