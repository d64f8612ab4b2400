// Horizons from points in the air over synthetic terrains with known answers: the bottom of a V
// valley, behind a ridge, above a flat DEM whose base plane goes on beyond its edge (the
// geometric dip), off the DEM, below the surface.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/util/angles.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/horizon_set.hpp"
#include "core/visibility/point_horizons.hpp"
#include "tests/visibility/synthetic_terrain.hpp"

namespace ts::visibility {
namespace {

using testing::make_terrain;

// Cosine-weighted visible fraction of the sky over a horizontal receiver from D horizons:
// (1 / 2 pi) sum over slices of cos^2(max(h, 0)) dphi.
double cosine_visible_fraction(const std::vector<float>& h) {
    double sum = 0;
    for (float a : h) sum += std::pow(std::cos(std::max(0.0, double(a))), 2);
    return sum / double(h.size());
}

TEST(PointHorizons, BottomOfAVValleyMatchesTheWallsAndTheAnalyticSkyFraction) {
    for (const double beta_deg : {15.0, 30.0, 45.0}) {
        const double t = std::tan(radians(beta_deg));
        // A valley along y (north-south), walls z = t |x|, 301 x 301 texels of 10 m.
        const auto terrain = make_terrain(301, 301, 10.0, 10.0, [&](double x, double) { return t * std::abs(x); });
        PointHorizons ph(terrain.grid, {.curvature = false});
        const int dirs = 64;
        std::vector<float> h(dirs);
        ph.horizons({150.0, 150.0}, 0.01, dirs, h.data());
        double worst = 0;
        for (int d = 0; d < dirs; ++d) {
            const double want = std::atan(t * std::abs(std::cos(azimuth_rad(d, dirs))));
            worst = std::max(worst, std::abs(h[std::size_t(d)] - want));
        }
        // The first step's bilinear sample is 2.5 m out: the 1 cm lift is all that differs.
        EXPECT_LT(worst, 2e-3) << beta_deg;
        // An infinitely long V valley leaves cos(beta) of the cosine-weighted sky.
        EXPECT_NEAR(cosine_visible_fraction(h), std::cos(radians(beta_deg)), 2e-3) << beta_deg;
    }
}

TEST(PointHorizons, APointBehindARidgeLosesTheSunInItsAzimuth) {
    // A ridge along y at x = 0: 300 m high, flanks falling 1:1 to a flat floor at 0.
    const auto terrain =
        make_terrain(201, 201, 20.0, 20.0, [](double x, double) { return std::max(0.0, 300.0 - std::abs(x)); });
    PointHorizons ph(terrain.grid, {.curvature = false});
    // 800 m east of the crest, 50 m up: the crest 250 m above it at 800 m, 17.35 deg.
    const glm::dvec2 at{100.0 + 40.0, 100.0};
    const double crest = degrees(std::atan(250.0 / 800.0));
    auto sun = [](double azimuth_cw_deg, double elevation_deg) {
        const double phi = radians(90.0 - azimuth_cw_deg), e = radians(elevation_deg);
        return glm::dvec3(std::cos(e) * std::cos(phi), std::cos(e) * std::sin(phi), std::sin(e));
    };
    constexpr double r = 0.004654;
    EXPECT_EQ(ph.sun_fraction(at, 50.0, sun(270, crest - 2), r), 0.0);   // west, below the crest: lost
    EXPECT_EQ(ph.sun_fraction(at, 50.0, sun(270, crest + 2), r), 1.0);   // above it
    EXPECT_EQ(ph.sun_fraction(at, 50.0, sun(90, crest - 10), r), 1.0);   // east: open
    EXPECT_NEAR(ph.sun_fraction(at, 50.0, sun(270, crest), r), 0.5, 0.15);  // the disc on the crest
    // Higher up the same point sees over it.
    EXPECT_EQ(ph.sun_fraction(at, 400.0, sun(270, 2), r), 1.0);
}

TEST(PointHorizons, TheBasePlaneBeyondTheEdgeGivesTheGeometricDip) {
    const auto terrain = make_terrain(101, 101, 30.0, 30.0, [](double, double) { return 200.0; });
    PointHorizons ph(terrain.grid, {.curvature = true});
    EXPECT_EQ(ph.base_height(), 200.0);
    const double h = 1000.0, c = curvature_factor(true);
    const int dirs = 16;
    std::vector<float> got(dirs);
    for (const glm::dvec2 at : {glm::dvec2(50, 50), glm::dvec2(100, 0), glm::dvec2(-300, 40), glm::dvec2(250, 250)}) {
        ph.horizons(at, 200.0 + h, dirs, got.data());
        for (float a : got) {
            // The dip atan(2 sqrt(h c)) = 1.02 deg at 1 km: the plane's horizon is 113 km away.
            EXPECT_NEAR(a, -std::atan(2.0 * std::sqrt(h * c)), 1e-6) << at.x << "," << at.y;
        }
    }
    // Without curvature the plane's horizon is the horizontal.
    PointHorizons flat(terrain.grid, {.curvature = false});
    flat.horizons({50, 50}, 1200.0, dirs, got.data());
    for (float a : got) EXPECT_NEAR(a, 0.0, 1e-9);
}

TEST(PointHorizons, OffTheDemItSeesTheDemAndBelowTheSurfaceItIsDark) {
    // A 500 m block in the middle of a flat plain at 0.
    const auto terrain = make_terrain(101, 101, 10.0, 10.0, [](double x, double y) {
        return std::abs(x) < 200 && std::abs(y) < 200 ? 500.0 : 0.0;
    });
    PointHorizons ph(terrain.grid, {.curvature = false});
    // 500 m west of the DEM's west edge, 10 m up, looking east (d = 0): the block's west face
    // (col 30, 800 m away) rises 490 m.
    float h[4];
    ph.horizons({-50.0, 50.0}, 10.0, 4, h);
    EXPECT_NEAR(h[0], std::atan(490.0 / 800.0), 0.01);
    EXPECT_NEAR(h[2], 0.0, 1e-9);  // west: the base plane
    for (float a : h) EXPECT_TRUE(std::isfinite(a));
    // Inside the block, 100 m below its top: every horizon near the zenith.
    ph.horizons({50.0, 50.0}, 400.0, 4, h);
    for (float a : h) EXPECT_GT(a, radians(85.0));
    // Below the base plane, off the DEM: the plane right next to it hides all but the zenith.
    ph.horizons({-50.0, 50.0}, -10.0, 4, h);
    for (float a : h) EXPECT_GT(a, radians(85.0));
}

}  // namespace
}  // namespace ts::visibility
