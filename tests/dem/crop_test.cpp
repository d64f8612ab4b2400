#include <gtest/gtest.h>

#include "core/dem/crop.hpp"
#include "core/dem/read_dem.hpp"
#include "core/util/error.hpp"

using namespace ts::dem;
namespace fs = std::filesystem;

TEST(Crop, GeographicBoxKeepsTheCellsItOverlaps) {
    const Dem d = read_dem(fs::path(TS_SHARED_DATA) / "dem" / "N00E010.hgt");
    const Dem c = crop(d, {10.25, 0.5, 10.5, 0.75});
    // Cell edges fall on (k - 0.5)/1200 deg: the box covers 301 cells each way.
    EXPECT_EQ(c.width, 301);
    EXPECT_EQ(c.height, 301);
    const glm::dvec2 ul = c.georef.pixel_to_lonlat(0, 0), lr = c.georef.pixel_to_lonlat(c.width, c.height);
    EXPECT_LE(ul.x, 10.25);
    EXPECT_GE(lr.x, 10.5);
    EXPECT_GE(ul.y, 0.75);
    EXPECT_LE(lr.y, 0.5);
    EXPECT_GT(ul.x, 10.25 - 1.0 / 1200);  // no more than one cell beyond the box
    // Heights are the same cells as in the full tile.
    const glm::dvec2 p = d.georef.crs_to_pixel(c.georef.pixel_to_crs(0.5, 0.5));
    EXPECT_EQ(c.at(0, 0), d.at(int(p.x), int(p.y)));
}

TEST(Crop, ProjectedGridUsesTheBoxFootprint) {
    Dem d;
    d.width = d.height = 100;
    d.z.assign(10000, 1.0f);
    d.void_mask.assign(10000, 0);
    auto utm = ts::geo::Crs::from_epsg(32633);
    const glm::dvec2 o = utm->from_lonlat({15.0, 45.0});
    d.georef = ts::geo::Georef(100, 100, {o.x - 1500, 30, 0, o.y + 1500, 0, -30}, utm, true);
    const Dem c = crop(d, {14.995, 44.995, 15.005, 45.005});  // ~790 m x 1110 m around the centre
    EXPECT_NEAR(c.width, 27, 1);
    EXPECT_NEAR(c.height, 38, 1);
}

TEST(Crop, BadBoxesThrow) {
    const Dem d = read_dem(fs::path(TS_SHARED_DATA) / "dem" / "N00E010.hgt");
    EXPECT_THROW(crop(d, {20, 0, 21, 1}), ts::InputError);        // misses the tile
    EXPECT_THROW(crop(d, {10.5, 0.2, 10.4, 0.3}), ts::InputError);  // W > E
}
