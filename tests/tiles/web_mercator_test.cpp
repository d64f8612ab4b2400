// Web Mercator tile math: bounds, point -> tile, TMS rows, quadkeys, the global pixel grid.
#include "core/tiles/web_mercator.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace ts::tiles {
namespace {

TEST(WebMercator, ZoomZeroIsTheSquareWorld) {
    const MercatorBounds b = tile_bounds({0, 0, 0});
    EXPECT_DOUBLE_EQ(b.x0, -kOriginShiftM);
    EXPECT_DOUBLE_EQ(b.x1, kOriginShiftM);
    EXPECT_DOUBLE_EQ(b.y0, -kOriginShiftM);
    EXPECT_DOUBLE_EQ(b.y1, kOriginShiftM);
    EXPECT_NEAR(mercator_to_lonlat({0, kOriginShiftM}).y, kMaxLatitudeDeg, 1e-9);
}

TEST(WebMercator, TileBoundsMatchGdal2tilesFigures) {
    // gdal2tiles' GlobalMercator.TileBounds(1, 1, 1) (TMS row 1 = XYZ row 0 at z1).
    const MercatorBounds b = tile_bounds({1, 1, 0});
    EXPECT_DOUBLE_EQ(b.x0, 0.0);
    EXPECT_DOUBLE_EQ(b.y0, 0.0);
    EXPECT_NEAR(b.x1, 20037508.342789244, 1e-6);
    EXPECT_NEAR(b.y1, 20037508.342789244, 1e-6);
}

TEST(WebMercator, PointToTileAndBack) {
    // Anatolia: 40.5E 39.5N at z10.
    const glm::dvec2 m = lonlat_to_mercator({40.5, 39.5});
    const TileId t = tile_at(m.x, m.y, 10);
    EXPECT_EQ(t.x, int(std::floor((40.5 + 180.0) / 360.0 * 1024)));
    const double lat = 39.5 * 3.14159265358979323846 / 180.0;
    EXPECT_EQ(t.y, int(std::floor((1.0 - std::asinh(std::tan(lat)) / 3.14159265358979323846) / 2.0 * 1024)));
    const MercatorBounds b = tile_bounds(t);
    EXPECT_LE(b.x0, m.x);
    EXPECT_GT(b.x1, m.x);
    EXPECT_LE(b.y0, m.y);
    EXPECT_GT(b.y1, m.y);
    const glm::dvec2 back = mercator_to_lonlat(m);
    EXPECT_NEAR(back.x, 40.5, 1e-12);
    EXPECT_NEAR(back.y, 39.5, 1e-12);
}

TEST(WebMercator, TmsRowFlipIsItsOwnInverse) {
    EXPECT_EQ(tms_row(0, 0), 0);
    EXPECT_EQ(tms_row(3, 0), 7);
    EXPECT_EQ(tms_row(3, 5), 2);
    EXPECT_EQ(tms_row(12, tms_row(12, 1234)), 1234);
}

TEST(WebMercator, QuadkeysAsBingDocumentsThem) {
    EXPECT_EQ(quadkey({3, 3, 5}), "213");  // the example of Bing Maps Tile System
    EXPECT_EQ(quadkey({0, 0, 0}), "");
    const TileId t = from_quadkey("0231010");
    EXPECT_EQ(quadkey(t), "0231010");
    EXPECT_THROW(from_quadkey("014"), std::invalid_argument);
}

TEST(WebMercator, PixelCentresAreOneGridPerPixelZoom) {
    // The 256-px tile (z, 2x+1, 2y) and the 512-px tile (z-1, x, y) hold the same global pixels:
    // their centres are the same numbers.
    const int x = 617;
    const int p = 11;  // 256-px tiles at z11, 512-px tiles at z10: pixel zoom 11
    for (int i : {0, 1, 255}) {
        const std::int64_t small = std::int64_t(2 * x + 1) * 256 + i;
        const std::int64_t large = std::int64_t(x) * 512 + 256 + i;
        EXPECT_EQ(small, large);
        EXPECT_EQ(pixel_centre_m(small, p), pixel_centre_m(large, p));
    }
    EXPECT_NEAR(pixel_size_m(0), 156543.03392804097, 1e-6);
    EXPECT_NEAR(pixel_centre_m(0, 0), -kOriginShiftM + 0.5 * pixel_size_m(0), 1e-6);
    EXPECT_EQ(tile_size_shift(256), 0);
    EXPECT_EQ(tile_size_shift(512), 1);
    EXPECT_EQ(tile_size_shift(300), -1);
}

}  // namespace
}  // namespace ts::tiles
