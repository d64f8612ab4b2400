// --exaggeration auto raises a zoom's exaggeration where its level's relief is too gentle to read.
#include "core/tiles/legible_relief.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/dem/read_dem.hpp"
#include "core/tiles/tile_export.hpp"
#include "core/tiles/zoom_exaggeration.hpp"
#include "core/util/angles.hpp"

namespace ts::tiles {
namespace {

const double kTarget = std::tan(radians(kLegibleSlopeDeg));
const std::string kEtopo = std::string(TS_SHARED_DATA) + "/dem/etopo1_global_1deg.tif";
const std::string kAnatolia = std::string(TS_SHARED_DATA) + "/dem/srtm3_N39E040_1000px.tif";

// A projected DEM of `n` x `n` texels of `spacing` metres whose height is f(col, row).
template <class F>
dem::Dem projected(int n, double spacing, F f) {
    dem::Dem d;
    d.width = d.height = n;
    geo::GeoTransform t;
    t.x0 = 500000, t.dx_col = spacing, t.y0 = 5000000, t.dy_row = -spacing;
    d.georef = geo::Georef(n, n, t, geo::Crs::from_epsg(32631), true);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) d.z.push_back(float(f(c, r)));
    d.void_mask.assign(d.z.size(), 0);
    return d;
}

TEST(LegibleRelief, RaisesTowardsTheTargetWithinItsBounds) {
    EXPECT_DOUBLE_EQ(legible_exaggeration(1.0, 0.001), 1.0);           // zoom 12+: true heights
    EXPECT_DOUBLE_EQ(legible_exaggeration(4.0, 0.0), 4.0);             // no slopes: nothing to read
    EXPECT_DOUBLE_EQ(legible_exaggeration(4.0, kTarget), 4.0);         // steep already
    EXPECT_NEAR(legible_exaggeration(4.0, kTarget / 10), 10.0, 1e-9);  // raised to the target
    EXPECT_DOUBLE_EQ(legible_exaggeration(4.0, kTarget / 100), 16.0);  // at most 4 E
    EXPECT_DOUBLE_EQ(legible_exaggeration(1.5, kTarget / 100), 2.25);  // and E^2 near zoom 12
}

TEST(LegibleRelief, SteepSlopeOfAPlaneIsItsGradient) {
    // 3 m up per 30 m texel eastwards and 4 m southwards: tan slope hypot(0.1, 4/30), to UTM's
    // scale factor on the ground (0.9996 at the central meridian).
    const dem::Dem plane = projected(300, 30.0, [](int c, int r) { return 3.0 * c + 4.0 * r; });
    EXPECT_NEAR(steep_slope(plane, 0), std::hypot(0.1, 4.0 / 30), 1e-4);
    // Level 2 averages 4 x 4 texels: the same plane at 120 m.
    EXPECT_NEAR(steep_slope(plane, 2), std::hypot(0.1, 4.0 / 30), 1e-4);
}

TEST(LegibleRelief, OnASeaFloorDemOnlyLandCounts) {
    // Land (x < 150) rises gently at 0.01; the sea floor beyond falls steeply to -5000 m.
    const dem::Dem d =
        projected(300, 100.0, [](int c, int) { return c < 150 ? 10.0 + 1.0 * c : -20.0 * (c - 150) - 1000.0; });
    EXPECT_NEAR(steep_slope(d, 0), 0.01, 1e-5);
    // Without a sea floor (nothing below -1000 m) every texel counts: the steep half wins.
    const dem::Dem shallow =
        projected(300, 100.0, [](int c, int) { return c < 150 ? 10.0 + 1.0 * c : -2.0 * (c - 150); });
    EXPECT_NEAR(steep_slope(shallow, 0), 0.02, 1e-5);
}

// ETOPO1 at 1 degree: its zoom-2 relief was faint at E(P) = 16; it is raised to the bound.
// The 90 m Anatolia DEM is steep enough at every zoom it covers and keeps E(P).
TEST(LegibleRelief, GlobalGridIsRaisedMountainsAreNot) {
    const dem::Dem etopo = dem::read_dem(kEtopo);
    const double land = steep_slope(etopo, 0);
    EXPECT_GT(land, std::tan(radians(0.3)));
    EXPECT_LT(land, std::tan(radians(0.6)));
    const TileJob job;
    for (const int pz : {0, 2, 4}) {
        const ZoomShading z = zoom_shading(etopo, job, pz);
        EXPECT_DOUBLE_EQ(z.rule_exaggeration, 16.0) << pz;  // past the native zoom 0
        EXPECT_GT(z.vertical_scale, 50.0) << pz;
        EXPECT_LE(z.vertical_scale, 64.0) << pz;
    }
    const dem::Dem anatolia = dem::read_dem(kAnatolia);
    for (int pz = 3; pz <= 12; ++pz) {
        const ZoomShading z = zoom_shading(anatolia, job, pz);
        EXPECT_DOUBLE_EQ(z.vertical_scale, z.rule_exaggeration) << pz;
    }
}

}  // namespace
}  // namespace ts::tiles
