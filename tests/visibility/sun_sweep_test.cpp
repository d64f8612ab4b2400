// The sun sweep (core/visibility/sun_sweep.hpp) against the exact path (sun_visibility) on
// real DEM crops and synthetic terrains, an analytic shadow (a plateau's edge), voids, grid
// edges, reuse across frames and bad input.
#include "core/util/angles.hpp"
#include "core/visibility/sun_sweep.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "core/dem/read_dem.hpp"
#include "core/terrain/grid_crop.hpp"
#include "core/util/error.hpp"
#include "core/visibility/sun_visibility.hpp"
#include "core/visibility/visibility_grid.hpp"
#include "synthetic_terrain.hpp"
#include "tests/support/shared_data.hpp"

using namespace ts::visibility;
using ts::visibility::testing::make_terrain;
using ts::radians;
namespace fs = std::filesystem;

namespace {


struct Agreement {
    double iou = 1, mae = 0;
    long nan_mismatch = 0, shadow_exact = 0, shadow_sweep = 0;
    int first_diff_col = -1, first_diff_row = -1;
};

// Shadow masks (fraction < 0.5) and mean |fraction difference| over the valid texels.
Agreement compare(const std::vector<float>& exact, const std::vector<float>& sweep, int width) {
    Agreement a;
    long inter = 0, uni = 0, n = 0;
    double sum = 0;
    for (std::size_t i = 0; i < exact.size(); ++i) {
        const bool ne = std::isnan(exact[i]), ns = std::isnan(sweep[i]);
        if (ne != ns) ++a.nan_mismatch;
        if (ne || ns) continue;
        const bool se = exact[i] < 0.5f, ss = sweep[i] < 0.5f;
        if (se != ss && a.first_diff_col < 0) a.first_diff_col = int(i % width), a.first_diff_row = int(i / width);
        inter += se && ss;
        uni += se || ss;
        a.shadow_exact += se;
        a.shadow_sweep += ss;
        sum += std::abs(double(exact[i]) - sweep[i]);
        ++n;
    }
    a.iou = uni > 0 ? double(inter) / double(uni) : 1.0;
    a.mae = n > 0 ? sum / double(n) : 0.0;
    return a;
}

// The central n x n texels of a grid, with its per-row spacing.
struct SunPosition {
    double azimuth_deg, elevation_deg;
};
// Grazing to high, axis-aligned and diagonal azimuths and a few in between.
const std::vector<SunPosition> kSuns = {{90, 3},  {45, 3},  {200, 2}, {0, 5},    {135, 5},   {270, 10},
                                        {315, 10}, {180, 20}, {30, 20}, {225, 35}, {112.5, 35}, {160, 60}};

// Every sun position: shadow-mask IoU >= min_iou and mean |fraction difference| <= max_mae,
// voids in the same places, curvature on (as the renderer).
void expect_agreement(const ts::terrain::HeightGrid& grid, const std::string& name, double min_iou, double max_mae,
                      bool curvature = true) {
    SunSweepOptions so;
    so.curvature = curvature;
    so.threads = 2;
    SunShadowSweep sweep(grid, so);
    SunVisibilityOptions eo;
    eo.curvature = curvature;
    eo.threads = 2;
    std::vector<float> fast;
    for (const SunPosition& sun : kSuns) {
        const std::vector<float> exact = sun_visibility(grid, sun.azimuth_deg, sun.elevation_deg, eo);
        sweep.compute(sun.azimuth_deg, sun.elevation_deg, fast);
        ASSERT_EQ(fast.size(), exact.size());
        const Agreement a = compare(exact, fast, grid.width);
        const std::string where = name + " az " + std::to_string(sun.azimuth_deg) + " el " +
                                  std::to_string(sun.elevation_deg) + ": shadowed exact " +
                                  std::to_string(a.shadow_exact) + ", sweep " + std::to_string(a.shadow_sweep) +
                                  ", first difference at col " + std::to_string(a.first_diff_col) + " row " +
                                  std::to_string(a.first_diff_row);
        EXPECT_GE(a.iou, min_iou) << where;
        EXPECT_LE(a.mae, max_mae) << where;
        EXPECT_EQ(a.nan_mismatch, 0) << where;
    }
}


// A plateau kPlateauTop high east of column kPlateauEdge over flat ground.
constexpr int kPlateauWidth = 120, kPlateauHeight = 40, kPlateauEdge = 90;
constexpr double kPlateauSpacing = 10.0, kPlateauTop = 50.0;
std::vector<float> plateau_heights() {
    std::vector<float> z(std::size_t(kPlateauWidth) * kPlateauHeight, 0.0f);
    for (int r = 0; r < kPlateauHeight; ++r)
        for (int c = kPlateauEdge; c < kPlateauWidth; ++c) z[std::size_t(r) * kPlateauWidth + c] = float(kPlateauTop);
    return z;
}

SunSweepOptions without_curvature() {
    SunSweepOptions so;
    so.curvature = false;
    return so;
}

// The plateau's heights, its grid and a sweep over it without curvature (the analytic shadow has none).
struct Plateau {
    std::vector<float> z = plateau_heights();
    ts::terrain::HeightGrid grid = ts::terrain::HeightGrid::uniform(kPlateauWidth, kPlateauHeight, z, kPlateauSpacing, kPlateauSpacing);
    SunShadowSweep sweep{grid, without_curvature()};
};

}  // namespace

// Real DEMs (projected-like and geographic, mountains and equatorial relief): the masks agree
// to IoU >= 0.99 and the fractions to a mean of 0.005 at every sun position.
TEST(SunSweep, AgreesWithExactOnRealDems) {
    for (const std::string name : {"copernicus_N45E005_grenoble_500px.tif", "srtm3_N39E040_1000px.tif", "N00E010.hgt"}) {
        const ts::dem::Dem dem = ts::dem::read_dem(ts::test::shared_dem(name));
        const VisibilityGrid vgrid(dem);
        const ts::terrain::GridCrop crop = ts::terrain::centre_crop(vgrid.view(), 160, 160);
        expect_agreement(crop.grid, name, 0.99, 0.005);
    }
}

// A global 1-degree grid: rows from pole to pole, whose east-west spacing shrinks 100-fold.
// Few texels are shadowed there (slopes over 111 km are gentle), so the IoU is of a handful.
TEST(SunSweep, AgreesWithExactOnAGlobalGrid) {
    const ts::dem::Dem dem = ts::dem::read_dem(ts::test::shared_dem("etopo1_global_1deg.tif"));
    const VisibilityGrid vgrid(dem);
    expect_agreement(vgrid.view(), "etopo1", 0.9, 0.002);
}

// Synthetic hills on a geographic-like grid (dx shrinking with latitude, as at 60 N).
TEST(SunSweep, AgreesWithExactWhereRowSpacingVaries) {
    auto t = make_terrain(180, 150, 30.0, 30.0, ts::visibility::testing::hills);
    for (int r = 0; r < t.grid.height; ++r) t.grid.dx_m[std::size_t(r)] = 30.0 * std::cos(radians(58.0 + 0.02 * r));
    expect_agreement(t.grid, "hills at 60N", 0.99, 0.005, /*curvature=*/false);
}

// A plateau of height H east of column x0 over flat ground, sun from the east: ground at
// distance d from the edge sees it at tan = H / d, so the fraction is known in closed form.
TEST(SunSweep, PlateauEdgeCastsTheAnalyticShadow) {
    const int w = kPlateauWidth, h = kPlateauHeight, x0 = kPlateauEdge;
    const double dx = kPlateauSpacing, height = kPlateauTop;
    Plateau plateau;
    SunShadowSweep& sweep = plateau.sweep;
    for (double el : {3.0, 10.0, 30.0}) {
        const std::vector<float> v = sweep.compute(90.0, el);
        for (int r = 0; r < h; ++r)
            for (int c = 0; c + 1 < x0; ++c) {
                const double horizon = std::atan(height / ((x0 - c) * dx));
                const double want = sun_disc_visible_fraction(horizon, radians(el), sweep.options().sun_radius_rad);
                ASSERT_NEAR(v[std::size_t(r) * w + c], want, 1e-3) << "el " << el << " col " << c << " row " << r;
            }
    }
}

// A cone on flat ground, sun at 10 degrees from the south-west: the ground is shadowed where
// the ray towards the sun passes under the cone's surface (found by a fine 1-D search). Texels
// whose ray clears or meets the cone by less than one texel's rise of its flank (6 m) are not
// judged: the texelised cone (bilinear between texel centres) differs from the true one by that.
TEST(SunSweep, ConeCastsItsShadow) {
    const int n = 101;
    const double dx = 10.0, height = 120.0, radius = 200.0;
    auto cone = [&](double x, double y) { return std::max(0.0, height * (1.0 - std::hypot(x, y) / radius)); };
    auto t = make_terrain(n, n, dx, dx, cone);
    SunSweepOptions so;
    so.curvature = false;
    so.sun_radius_rad = 0;  // a point sun: the mask is the shadow itself
    SunShadowSweep sweep(t.grid, so);
    const double az = radians(225), el = radians(10);
    const double ux = std::sin(az), uy = std::cos(az);  // east, north towards the sun
    const std::vector<float> v = sweep.compute(225.0, 10.0);
    SunVisibilityOptions eo;
    eo.curvature = false;
    eo.sun_radius_rad = 0;
    const std::vector<float> exact = sun_visibility(t.grid, 225.0, 10.0, eo);
    int judged = 0, shadowed = 0;
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            const double x = (c - n / 2) * dx, y = (n / 2 - r) * dx;
            if (std::hypot(x, y) < radius + 1.5 * dx) continue;  // on or next to the cone: its texels decide
            // Rays grazing the rim meet the texelised cone but maybe not the true one.
            const double along = -(x * ux + y * uy);  // where the ray passes closest to the apex
            const double closest = along > 0 ? std::abs(x * uy - y * ux) : std::hypot(x, y);
            if (std::abs(closest - radius) < 1.5 * dx) continue;
            double margin = -1e9;  // highest (cone - ray) where the ray passes over the cone
            for (double s = 0.5; s < 2 * radius + 2 * std::hypot(x, y); s += 0.5) {
                const double zc = cone(x + s * ux, y + s * uy);
                if (zc > 0) margin = std::max(margin, zc - s * std::tan(el));
            }
            if (std::abs(margin) < height / radius * dx) continue;
            ++judged;
            shadowed += margin > 0;
            EXPECT_EQ(v[std::size_t(r) * n + c] < 0.5f, margin > 0) << "col " << c << " row " << r;
            EXPECT_EQ(exact[std::size_t(r) * n + c] < 0.5f, margin > 0) << "exact: col " << c << " row " << r;
        }
    EXPECT_GT(judged, n * n / 2);
    EXPECT_GT(shadowed, 100);  // the test sees a real shadow
}

// Voids neither cast nor receive: NaN out exactly where the exact path has NaN, the rest agrees.
TEST(SunSweep, VoidsNeitherCastNorReceive) {
    auto t = make_terrain(120, 100, 30.0, 30.0, ts::visibility::testing::hills);
    for (int r = 30; r < 45; ++r)
        for (int c = 50; c < 70; ++c) t.z[std::size_t(r) * 120 + c] = std::numeric_limits<float>::quiet_NaN();
    t.z[5] = std::numeric_limits<float>::quiet_NaN();  // a lone void on the edge
    expect_agreement(t.grid, "hills with voids", 0.99, 0.005, /*curvature=*/false);
    // A void wall that would otherwise cast a long shadow over flat ground casts none.
    std::vector<float> z(60 * 20, 0.0f);
    for (int r = 0; r < 20; ++r) z[std::size_t(r) * 60 + 40] = std::numeric_limits<float>::quiet_NaN();
    const auto grid = ts::terrain::HeightGrid::uniform(60, 20, z, 10.0, 10.0);
    const std::vector<float> v = SunShadowSweep(grid).compute(90.0, 5.0);
    for (int r = 0; r < 20; ++r)
        for (int c = 0; c < 60; ++c) {
            if (c == 40)
                EXPECT_TRUE(std::isnan(v[std::size_t(r) * 60 + c]));
            else
                EXPECT_FLOAT_EQ(v[std::size_t(r) * 60 + c], 1.0f) << c << "," << r;
        }
}

// Tiny and thin grids, texels on the edge facing the sun (nothing beyond: fully lit on flat
// ground), one object reused for many suns equals a fresh one, and the thread count does not
// change the result.
TEST(SunSweep, EdgesTinyGridsReuseAndThreads) {
    for (auto [w, h] : {std::pair{1, 1}, std::pair{1, 7}, std::pair{9, 1}, std::pair{2, 2}}) {
        std::vector<float> z(std::size_t(w) * h, 100.0f);
        const auto grid = ts::terrain::HeightGrid::uniform(w, h, z, 30.0, 30.0);
        SunShadowSweep sweep(grid);
        for (double az : {0.0, 45.0, 90.0, 200.0}) {
            const std::vector<float> v = sweep.compute(az, 10.0);
            ASSERT_EQ(v.size(), z.size());
            for (float f : v) EXPECT_FLOAT_EQ(f, 1.0f) << w << "x" << h << " az " << az;
        }
    }
    auto t = make_terrain(90, 70, 30.0, 30.0, ts::visibility::testing::hills);
    SunSweepOptions one;
    one.threads = 1;
    SunSweepOptions two;
    two.threads = 2;
    SunShadowSweep reused(t.grid, two);
    for (const SunPosition& sun : kSuns) {
        const std::vector<float> a = reused.compute(sun.azimuth_deg, sun.elevation_deg);
        const std::vector<float> fresh = SunShadowSweep(t.grid, one).compute(sun.azimuth_deg, sun.elevation_deg);
        ASSERT_EQ(a.size(), fresh.size());
        for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], fresh[i]) << i;
    }
}

TEST(SunSweep, BadInputIsAnInputError) {
    auto t = make_terrain(20, 20, 30.0, 30.0, ts::visibility::testing::hills);
    SunShadowSweep sweep(t.grid);
    EXPECT_THROW(sweep.compute(0.0, 95.0), ts::InputError);
    EXPECT_THROW(sweep.compute(std::nan(""), 10.0), ts::InputError);
    EXPECT_THROW(sweep.compute(0.0, std::numeric_limits<double>::infinity()), ts::InputError);
    SunSweepOptions bad;
    bad.sun_radius_rad = -1;
    EXPECT_THROW(SunShadowSweep(t.grid, bad), ts::InputError);
    bad = {};
    bad.near_field_texels = -1;
    EXPECT_THROW(SunShadowSweep(t.grid, bad), ts::InputError);
    bad = {};
    bad.near_field_step_texels = 0;
    EXPECT_THROW(SunShadowSweep(t.grid, bad), ts::InputError);
    std::vector<float> z(10, 0.0f);
    ts::terrain::HeightGrid wrong = ts::terrain::HeightGrid::uniform(4, 4, z, 1.0, 1.0);  // 10 heights for 16
    EXPECT_THROW(SunShadowSweep{wrong}, ts::InputError);
    ts::terrain::HeightGrid empty;
    EXPECT_THROW(SunShadowSweep{empty}, ts::InputError);
    EXPECT_EQ(parse_sun_method("sweep"), SunMethod::sweep);
    EXPECT_EQ(parse_sun_method("exact"), SunMethod::exact);
    EXPECT_THROW(parse_sun_method("fast"), ts::InputError);
}

// The horizon the sweep gives beside the fraction (compute's horizon_above_sun, what the
// flythrough interpolates between texels to place a shadow's edge inside them) places the edges
// where the exact path's horizon does; asking for it leaves the fraction as it was, and the
// fraction is the disc's above it.
TEST(SunSweep, TheHorizonItGivesPlacesShadowEdgesAsTheExactOne) {
    const ts::dem::Dem dem = ts::dem::read_dem(ts::test::shared_dem("copernicus_N45E005_grenoble_500px.tif"));
    const VisibilityGrid vgrid(dem);
    const ts::terrain::GridCrop crop = ts::terrain::centre_crop(vgrid.view(), 160, 160);
    SunSweepOptions so;
    so.threads = 2;
    SunShadowSweep sweep(crop.grid, so);
    SunVisibilityOptions eo;
    eo.threads = 2;
    const double band = kSunHorizonBandRad;
    for (const SunPosition& sun : kSuns) {
        std::vector<float> plain, fraction, horizon, exact_horizon;
        sweep.compute(sun.azimuth_deg, sun.elevation_deg, plain);
        sweep.compute(sun.azimuth_deg, sun.elevation_deg, fraction, &horizon);
        const std::vector<float> exact = sun_visibility(crop.grid, sun.azimuth_deg, sun.elevation_deg, eo, &exact_horizon);
        ASSERT_EQ(horizon.size(), plain.size());
        // What a view does with it: along each row, between a texel the exact path finds lit and
        // a neighbour it finds shaded, the shadow's edge falls where the horizon interpolated
        // linearly crosses the sun. Where the sweep's and the exact horizons put it, in texels.
        std::vector<double> edge_shift;
        double worst_fraction = 0;
        const int w = crop.grid.width;
        for (std::size_t t = 0; t < plain.size(); ++t) {
            ASSERT_NEAR(fraction[t], plain[t], 1e-6) << t;
            ASSERT_LE(std::abs(horizon[t]), band * (1 + 1e-6));
            ASSERT_LE(std::abs(exact_horizon[t]), band * (1 + 1e-6));
            const double e = radians(sun.elevation_deg);
            worst_fraction = std::max(
                worst_fraction, std::abs(sun_disc_visible_fraction(e + horizon[t], e, so.sun_radius_rad) - fraction[t]));
            if (int(t % std::size_t(w)) + 1 == w) continue;
            const double ea = exact_horizon[t], eb = exact_horizon[t + 1], sa = horizon[t], sb = horizon[t + 1];
            if ((ea < 0) == (eb < 0) || (sa < 0) == (sb < 0)) continue;
            edge_shift.push_back(std::abs(ea / (ea - eb) - sa / (sa - sb)));
        }
        std::sort(edge_shift.begin(), edge_shift.end());
        const auto at = [&](double q) { return edge_shift.empty() ? 0.0 : edge_shift[std::size_t(q * double(edge_shift.size() - 1))]; };
        std::printf("az %5.1f el %4.1f: %zu edges between texels, the sweep's against the exact horizon's: median %.3f, "
                    "p90 %.3f texel; fraction from the horizon within %.2g\n",
                    sun.azimuth_deg, sun.elevation_deg, edge_shift.size(), at(0.5), at(0.9), worst_fraction);
        // Measured: medians 0, p90 up to 0.13 texel with the sun 2 degrees up, 0 from 10 degrees.
        EXPECT_LE(at(0.5), 0.01);
        EXPECT_LE(at(0.9), 0.2);
        EXPECT_LE(worst_fraction, 1e-4);
    }
}

// A plateau's edge: ground at distance d sees its top at atan(H / d); the horizon given is that
// less the sun's elevation where the ground is shaded or near the edge.
TEST(SunSweep, TheHorizonItGivesBesideAPlateauIsAnalytic) {
    const int w = kPlateauWidth, x0 = kPlateauEdge;
    const double dx = kPlateauSpacing, height = kPlateauTop;
    Plateau plateau;
    SunShadowSweep& sweep = plateau.sweep;
    const double el = 10.0, e = radians(el);
    std::vector<float> v, rel;
    sweep.compute(90.0, el, v, &rel);
    // Shaded ground sees the edge; lit ground nearer than the near field (8 texels) too.
    // Farther lit ground keeps the occluder highest at the sun's elevation (the ground 8
    // texels away outdoes the plateau there): its horizon is a lower bound.
    int exact = 0;
    for (int c = 0; c + 1 < x0; ++c) {
        const double want = std::clamp(std::atan(height / ((x0 - c) * dx)) - e, -kSunHorizonBandRad, kSunHorizonBandRad);
        const float got = rel[std::size_t(20 * w + c)];
        if (want >= -1e-3 || x0 - c <= 8) {
            ++exact;
            EXPECT_NEAR(got, want, 2e-3) << c;
        } else {
            EXPECT_LE(got, want + 1e-6) << c;
        }
    }
    EXPECT_GT(exact, 20);
}
