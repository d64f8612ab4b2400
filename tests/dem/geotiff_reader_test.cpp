#include <cmath>

#include <gtest/gtest.h>

#include "core/dem/read_dem.hpp"
#include "tests/dem/dem_test_files.hpp"

using namespace ts::dem;
namespace fs = std::filesystem;

TEST(GeoTiffReader, SharedSrtmCropIsInt16WithTiepointAndScale) {
    const Dem d = read_dem(fs::path(TS_SHARED_DATA) / "dem" / "srtm3_N39E040_1000px.tif");
    EXPECT_EQ(d.width, 1000);
    EXPECT_EQ(d.height, 1000);
    EXPECT_TRUE(d.georef.pixel_is_area());
    EXPECT_EQ(d.georef.crs().epsg(), 4326);
    const glm::dvec2 ul = d.georef.pixel_to_crs(0, 0), lr = d.georef.pixel_to_crs(1000, 1000);
    EXPECT_NEAR(ul.x, 40.0, 1e-12);
    EXPECT_NEAR(ul.y, 40.0, 1e-12);
    EXPECT_NEAR(lr.x, 40.0 + 1000.0 / 1200, 1e-12);
    EXPECT_NEAR(lr.y, 40.0 - 1000.0 / 1200, 1e-12);
}

TEST(GeoTiffReader, PixelIsPointIsShiftedToEdges) {
    // gdalinfo: Origin = (4.999861111111112, 46.000138888888884) for this PixelIsPoint file.
    const Dem d = read_dem(fs::path(TS_SHARED_DATA) / "dem" / "copernicus_N45E005_grenoble_500px.tif");
    EXPECT_FALSE(d.georef.pixel_is_area());
    const glm::dvec2 ul = d.georef.pixel_to_crs(0, 0);
    EXPECT_NEAR(ul.x, 4.999861111111112, 1e-12);
    EXPECT_NEAR(ul.y, 46.000138888888884, 1e-12);
    EXPECT_EQ(d.vertical_datum, "EGM2008 geoid");  // from its DTED_VerticalDatum=E08 metadata
    EXPECT_EQ(d.credit.rfind("Copernicus DEM (TanDEM-X)", 0), 0u) << d.credit;  // DTED_DigitizingSystem=TANDEMX
}

TEST(GeoTiffReader, NodataValueAndFloatSamplesBecomeVoids) {
    const Dem d = read_dem(fs::path(TS_SHARED_DATA) / "dem" / "nodata_3x3.tif");
    EXPECT_EQ(d.void_count(), 4u);  // gdal: STATISTICS_VALID_PERCENT=55.56 of 9 cells
    EXPECT_TRUE(d.is_void(1, 1));
    EXPECT_EQ(d.at(0, 0), 2.0f);
}

TEST(GeoTiffReader, TiledAndStrippedLayoutsOfEveryTypeReadTheSame) {
    const fs::path dir = test_files::fresh_dir("tiff_types");
    const int w = 37, h = 21;  // not multiples of the 16x16 tiles nor the 2-row strips
    std::vector<float> f(std::size_t(w * h));
    for (int i = 0; i < w * h; ++i) f[std::size_t(i)] = float(i % 200) - 50.0f;
    struct Case { int bits, format; std::vector<std::uint8_t> bytes; };
    std::vector<Case> cases;
    { std::vector<std::int16_t> v(f.begin(), f.end()); cases.push_back({16, 2, test_files::as_bytes(v)}); }
    { std::vector<std::int32_t> v(f.begin(), f.end()); cases.push_back({32, 2, test_files::as_bytes(v)}); }
    { std::vector<double> v(f.begin(), f.end()); cases.push_back({64, 3, test_files::as_bytes(v)}); }
    cases.push_back({32, 3, test_files::as_bytes(f)});
    for (const Case& c : cases)
        for (bool tiled : {false, true}) {
            test_files::TiffSpec spec;
            spec.width = w;
            spec.height = h;
            spec.bits = c.bits;
            spec.sample_format = c.format;
            spec.tiled = tiled;
            const fs::path p = dir / ("t" + std::to_string(c.bits) + "_" + std::to_string(c.format) + (tiled ? "_tiled" : "") + ".tif");
            test_files::write_tiff(p, spec, c.bytes);
            const Dem d = read_dem(p);
            ASSERT_EQ(d.width, w);
            ASSERT_EQ(d.height, h);
            for (int i = 0; i < w * h; ++i) ASSERT_EQ(d.z[std::size_t(i)], f[std::size_t(i)]) << p << " cell " << i;
            EXPECT_EQ(d.void_count(), 0u);
        }
    // Unsigned 16-bit with a nodata value.
    std::vector<std::uint16_t> u(std::size_t(w * h), 700);
    u[5] = 65535;
    test_files::TiffSpec spec;
    spec.width = w;
    spec.height = h;
    spec.sample_format = 1;
    spec.nodata = "65535";
    test_files::write_tiff(dir / "u16.tif", spec, test_files::as_bytes(u));
    const Dem d = read_dem(dir / "u16.tif");
    EXPECT_EQ(d.void_count(), 1u);
    EXPECT_TRUE(d.is_void(5, 0));
    EXPECT_EQ(d.at(6, 0), 700.0f);
}

TEST(GeoTiffReader, TheCopyrightTagIsTheCreditAndSilenceIsNone) {
    // What maps of it credit by default (docs/tiles.md, "Attribution"); a mosaic credits each once.
    const fs::path dir = test_files::fresh_dir("tiff_credit");
    test_files::TiffSpec spec;
    spec.copyright = "Example Survey 2024, CC-BY 4.0  ";
    test_files::write_tiff(dir / "a.tif", spec, test_files::as_bytes(std::vector<std::int16_t>(12, 5)));
    EXPECT_EQ(read_dem(dir / "a.tif").credit, "Example Survey 2024, CC-BY 4.0");
    spec.copyright.clear();
    test_files::write_tiff(dir / "b.tif", spec, test_files::as_bytes(std::vector<std::int16_t>(12, 5)));
    EXPECT_EQ(read_dem(dir / "b.tif").credit, "");
}

TEST(GeoTiffReader, ProjectedEpsgKeyGivesAProjectedCrs) {
    const fs::path dir = test_files::fresh_dir("tiff_utm");
    test_files::TiffSpec spec;
    spec.epsg = 32733;
    spec.geographic = false;
    spec.x0 = 500000;
    spec.y0 = 9990000;
    spec.cell = 30;
    spec.pixel_is_point = true;
    test_files::write_tiff(dir / "utm.tif", spec, test_files::as_bytes(std::vector<std::int16_t>(12, 5)));
    const Dem d = read_dem(dir / "utm.tif");
    EXPECT_EQ(d.georef.crs().epsg(), 32733);
    EXPECT_FALSE(d.georef.crs().is_geographic());
    const glm::dvec2 ul = d.georef.pixel_to_crs(0, 0);
    EXPECT_DOUBLE_EQ(ul.x, 500000 - 15.0);  // tiepoint on the first centre, edge half a cell out
    EXPECT_DOUBLE_EQ(ul.y, 9990000 + 15.0);
}
