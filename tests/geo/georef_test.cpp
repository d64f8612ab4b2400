#include "core/geo/georef.hpp"
#include "core/util/angles.hpp"

#include <cmath>

#include <gtest/gtest.h>

using namespace ts::geo;
using ts::radians;

namespace {
// WGS84 radii of curvature at the equator: east-west = a, north-south = a(1 - e^2).
constexpr double kA = 6378137.0;
constexpr double kF = 1 / 298.257223563;
const double kE2 = kF * (2 - kF);
// A geodesic across one 3" cell equals the arc of the local radius to ~1e-9 relative; 1 mm
// is far above that and far below any convention error (half a cell, a wrong radius).
constexpr double kCellSizeToleranceM = 1e-3;

Georef srtm3_equator() {
    GeoTransform t;
    const double cell = 1.0 / 1200;
    t.x0 = 10 - cell / 2;
    t.dx_col = cell;
    t.y0 = 1 + cell / 2;
    t.dy_row = -cell;
    return Georef(1201, 1201, t, Crs::wgs84(), false);
}
}  // namespace

TEST(GeoTransform, InvertUndoesApplyIncludingRotation) {
    GeoTransform t{1000, 2.0, 0.5, 5000, -0.25, -3.0};
    const glm::dvec2 xy = t.apply(17.25, 42.5);
    const glm::dvec2 back = t.invert(xy.x, xy.y);
    EXPECT_NEAR(back.x, 17.25, 1e-12);
    EXPECT_NEAR(back.y, 42.5, 1e-12);
}

TEST(Georef, PixelCentresOfAnSrtmTileSitOnWholeDegrees) {
    const Georef g = srtm3_equator();
    const glm::dvec2 sw = g.pixel_to_lonlat(0.5, 1200.5);  // centre of the south-west cell
    EXPECT_NEAR(sw.x, 10.0, 1e-12);
    EXPECT_NEAR(sw.y, 0.0, 1e-12);
    const glm::dvec2 p = g.lonlat_to_pixel({11.0, 1.0});
    EXPECT_NEAR(p.x, 1200.5, 1e-9);
    EXPECT_NEAR(p.y, 0.5, 1e-9);
}

TEST(Georef, CellSizeOnAGeographicGridIsTheTrueMetricSpacing) {
    const Georef g = srtm3_equator();
    // Row at the equator: east-west spacing = a * dlon; north-south = meridian radius * dlat.
    const glm::dvec2 at_equator = g.cell_size_m(600.5, 1200.5);
    const double dlon = radians(1.0) / 1200;
    EXPECT_NEAR(at_equator.x, kA * dlon, kCellSizeToleranceM);
    EXPECT_NEAR(at_equator.y, kA * (1 - kE2) * dlon, kCellSizeToleranceM);

    // The same grid moved to 60N: east-west spacing shrinks with the parallel's radius.
    GeoTransform t = g.transform();
    t.y0 += 60;
    const Georef north(1201, 1201, t, Crs::wgs84(), false);
    const double phi = radians(60);
    const double parallel_radius = kA * std::cos(phi) / std::sqrt(1 - kE2 * std::sin(phi) * std::sin(phi));
    EXPECT_NEAR(north.cell_size_m(600.5, 1200.5).x, parallel_radius * dlon, kCellSizeToleranceM);
}

TEST(Georef, CellSizeOnUtmIncludesTheScaleFactor) {
    // 30 m cells on the central meridian of UTM 33N, where the scale factor is 0.9996.
    const auto crs = Crs::from_epsg(32633);
    const glm::dvec2 origin = crs->from_lonlat({15.0, 45.0});
    GeoTransform t{origin.x - 15, 30, 0, origin.y + 15, 0, -30};
    const Georef g(1, 1, t, crs, true);
    const glm::dvec2 size = g.cell_size_m();
    EXPECT_NEAR(size.x, 30 / 0.9996, 2e-3);  // 2 mm: the scale factor varies by 1e-8 across the cell
    EXPECT_NEAR(size.y, 30 / 0.9996, 2e-3);
}

TEST(Georef, GlobalGridOuterRowsDoNotBreakAtThePoles) {
    GeoTransform t{-180.5, 1, 0, 90.5, 0, -1};
    const Georef g(361, 181, t, Crs::wgs84(), true);
    const glm::dvec2 top = g.cell_size_m(180.5, 0.5);  // the row centred on the north pole
    EXPECT_TRUE(std::isfinite(top.x));
    EXPECT_TRUE(std::isfinite(top.y));
    EXPECT_LT(top.x, 1e-6);  // every meridian meets at the pole
}

TEST(Georef, WindowShiftsTheOrigin) {
    const Georef g = srtm3_equator();
    const Georef w = g.window(100, 200, 50, 60);
    EXPECT_EQ(w.width(), 50);
    EXPECT_EQ(w.height(), 60);
    const glm::dvec2 a = w.pixel_to_crs(0, 0), b = g.pixel_to_crs(100, 200);
    EXPECT_DOUBLE_EQ(a.x, b.x);
    EXPECT_DOUBLE_EQ(a.y, b.y);
    EXPECT_FALSE(w.pixel_is_area());
}

TEST(Georef, TrueNorthOnAGeographicOrWebMercatorGridIsTheGridsNorth) {
    EXPECT_EQ(srtm3_equator().grid_azimuth_of_north_deg(), 0.0);
    const auto mercator = Crs::from_epsg(3857);
    const glm::dvec2 o = mercator->from_lonlat({5.7, 45.2});
    const Georef g(100, 100, GeoTransform{o.x, 30, 0, o.y, 0, -30}, mercator, true);
    EXPECT_EQ(g.grid_azimuth_of_north_deg(), 0.0);
}

TEST(Georef, TrueNorthOnUtmIsTurnedByTheMeridianConvergence) {
    // 2.7 degrees east of UTM 31N's central meridian (3 E) at 45.2 N: true north lies west of
    // the grid's north by atan(tan(dlon) sin(lat)), 1.917 degrees (third-order terms ~1e-3).
    const auto crs = Crs::from_epsg(32631);
    const glm::dvec2 c = crs->from_lonlat({5.7, 45.2});
    const Georef g(100, 100, GeoTransform{c.x - 1500, 30, 0, c.y + 1500, 0, -30}, crs, true);
    const double expected = -std::atan(std::tan(radians(2.7)) * std::sin(radians(45.2))) * 180 / M_PI;
    EXPECT_NEAR(g.grid_azimuth_of_north_deg(), expected, 5e-3);
}

TEST(Georef, TrueNorthOnAPolarStereographicGridPointsAtThePole) {
    // EPSG:3413: grid north along 45 W; at 5.5 E true north lies 50.5 degrees west of it.
    const auto crs = Crs::from_epsg(3413);
    const glm::dvec2 c = crs->from_lonlat({5.5, 45.2});
    const Georef g(10, 10, GeoTransform{c.x - 500, 100, 0, c.y + 500, 0, -100}, crs, true);
    EXPECT_NEAR(g.grid_azimuth_of_north_deg(), -50.5, 1e-3);
}
