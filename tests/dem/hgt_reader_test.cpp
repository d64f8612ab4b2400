#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

#include "core/dem/read_dem.hpp"
#include "tests/dem/dem_test_files.hpp"

using namespace ts::dem;
namespace fs = std::filesystem;

TEST(HgtReader, SyntheticTileHasHeightsVoidsAndEdgeGeoref) {
    const fs::path dir = test_files::fresh_dir("hgt");
    test_files::write_bytes(dir / "S12W077.hgt", test_files::synthetic_hgt({{5, 7}}));
    const Dem d = read_dem(dir / "S12W077.hgt");
    ASSERT_EQ(d.width, 1201);
    ASSERT_EQ(d.height, 1201);
    EXPECT_EQ(d.at(3, 4), 7.0f);  // col + row, big-endian decoded
    EXPECT_EQ(d.at(1200, 1200), 2400.0f);
    EXPECT_TRUE(d.is_void(5, 7));
    EXPECT_TRUE(std::isnan(d.at(5, 7)));
    EXPECT_EQ(d.void_count(), 1u);
    EXPECT_FALSE(d.georef.pixel_is_area());
    EXPECT_EQ(d.georef.crs().epsg(), 4326);
    EXPECT_EQ(d.vertical_datum, "EGM96 geoid");
    EXPECT_EQ(d.credit, "SRTM (NASA, NGA)");
    // Centre of the south-west cell on (-77, -12); outer edge half a cell (1/2400 deg) beyond.
    const glm::dvec2 sw = d.georef.pixel_to_lonlat(0.5, 1200.5);
    EXPECT_NEAR(sw.x, -77.0, 1e-12);
    EXPECT_NEAR(sw.y, -12.0, 1e-12);
    const glm::dvec2 ul = d.georef.pixel_to_lonlat(0, 0);
    EXPECT_NEAR(ul.x, -77.0 - 0.5 / 1200, 1e-12);
    EXPECT_NEAR(ul.y, -11.0 + 0.5 / 1200, 1e-12);
}

TEST(HgtReader, SharedTileMatchesItsRawBytes) {
    const fs::path path = fs::path(TS_SHARED_DATA) / "dem" / "N00E010.hgt";
    const Dem d = read_dem(path);
    std::ifstream in(path, std::ios::binary);
    unsigned char b[2];
    in.seekg((600 * 1201 + 300) * 2);
    in.read(reinterpret_cast<char*>(b), 2);
    EXPECT_EQ(d.at(300, 600), float(std::int16_t(b[0] << 8 | b[1])));
    const glm::dvec2 ul = d.georef.pixel_to_crs(0, 0);
    EXPECT_NEAR(ul.x, 9.9995833333333337, 1e-12);  // gdalinfo's geoTransform
    EXPECT_NEAR(ul.y, 1.0004166666666667, 1e-12);
}

TEST(HgtReader, ZipHoldsTheSameTileAsItsContent) {
    const Dem d = read_dem(fs::path(TS_SHARED_DATA) / "dem" / "N00E011.hgt.zip");
    EXPECT_EQ(d.width, 1201);
    const glm::dvec2 sw = d.georef.pixel_to_lonlat(0.5, 1200.5);
    EXPECT_NEAR(sw.x, 11.0, 1e-12);
    EXPECT_NEAR(sw.y, 0.0, 1e-12);
    EXPECT_EQ(d.source, (fs::path(TS_SHARED_DATA) / "dem" / "N00E011.hgt.zip").string());
}
