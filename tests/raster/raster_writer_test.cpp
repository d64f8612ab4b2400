#include "core/raster/raster_writer.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "core/dem/read_dem.hpp"
#include "core/util/error.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using namespace ts;

namespace {

using ts::test::fresh_dir;

// gdalinfo -json of a file (GDAL is a test oracle only, never linked).
nlohmann::json gdalinfo(const fs::path& p, const std::string& flags = "") {
    const std::string cmd = "gdalinfo -json " + flags + " '" + p.string() + "' 2>/dev/null";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
    std::string out;
    std::array<char, 4096> buf{};
    while (pipe && fgets(buf.data(), int(buf.size()), pipe.get())) out += buf.data();
    return nlohmann::json::parse(out);
}

geo::Georef utm_georef(int w, int h, bool pixel_is_area) {
    return geo::Georef(w, h, {500020.0, 30.0, 0, 9990000.0, 0, -30.0}, geo::Crs::from_epsg(32733), pixel_is_area);
}

// Corner tolerance: gdalinfo prints corners with 3 decimals in metres, 7 in degrees.
constexpr double kGdalPrintedMetres = 5e-4;

}  // namespace

TEST(RasterWriter, FloatGeoTiffRoundTripsThroughOurReaderAndGdal) {
    const fs::path dir = fresh_dir("float");
    const int w = 7, h = 5;
    std::vector<float> data(std::size_t(w * h * 2));
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = float(i) * 0.5f - 3.0f;
    data[3] = NAN;
    for (bool area : {true, false}) {
        const geo::Georef g = utm_georef(w, h, area);
        // One band for our DEM reader (it takes single-band rasters), two for gdalinfo.
        const fs::path p1 = dir / (area ? "area1.tif" : "point1.tif");
        const fs::path p = dir / (area ? "area.tif" : "point.tif");
        raster::write_float_raster(p1, w, h, 1, data.data(), g);
        raster::write_float_raster(p, w, h, 2, data.data(), g, {"sky_visible", "svf"});

        const dem::Dem d = dem::read_dem(p1);
        EXPECT_EQ(d.width, w);
        EXPECT_EQ(d.georef.crs().epsg(), 32733);
        EXPECT_EQ(d.georef.pixel_is_area(), area);
        EXPECT_TRUE(d.is_void(3, 0));
        EXPECT_EQ(d.at(4, 0), data[4]);
        const glm::dvec2 a = d.georef.pixel_to_crs(0, 0), b = g.pixel_to_crs(0, 0);
        EXPECT_DOUBLE_EQ(a.x, b.x);
        EXPECT_DOUBLE_EQ(a.y, b.y);

        const nlohmann::json j = gdalinfo(p, "-stats");
        EXPECT_EQ(j["stac"]["proj:epsg"], 32733);
        EXPECT_EQ(j["bands"].size(), 2u);
        // Band-sequential planes: band 2 holds data[w*h ..], NaN skipped in band 1.
        EXPECT_EQ(j["bands"][0]["minimum"].get<double>(), -3.0);
        EXPECT_EQ(j["bands"][0]["maximum"].get<double>(), data[std::size_t(w * h - 1)]);
        EXPECT_EQ(j["bands"][1]["minimum"].get<double>(), data[std::size_t(w * h)]);
        EXPECT_EQ(j["bands"][1]["maximum"].get<double>(), data.back());
        EXPECT_EQ(j["bands"][1]["description"], "svf");
        EXPECT_TRUE(j["bands"][0]["noDataValue"].is_string());  // "nan"
        const auto& ul = j["cornerCoordinates"]["upperLeft"];
        const auto& lr = j["cornerCoordinates"]["lowerRight"];
        EXPECT_NEAR(ul[0].get<double>(), 500020.0, kGdalPrintedMetres);
        EXPECT_NEAR(ul[1].get<double>(), 9990000.0, kGdalPrintedMetres);
        EXPECT_NEAR(lr[0].get<double>(), 500020.0 + 30 * w, kGdalPrintedMetres);
        EXPECT_NEAR(lr[1].get<double>(), 9990000.0 - 30 * h, kGdalPrintedMetres);
    }
}

TEST(RasterWriter, UserDefinedCrsRoundTrips) {
    const fs::path dir = fresh_dir("userdef");
    auto crs = geo::Crs::from_definition("+proj=tmerc +lat_0=0 +lon_0=7.5 +k=1 +x_0=100000 +y_0=0 +ellps=GRS80 +units=m +no_defs +type=crs");
    const geo::Georef g(3, 3, {100000, 10, 0, 5000000, 0, -10}, crs, true);
    std::vector<float> data(9, 1.0f);
    raster::write_float_raster(dir / "tm.tif", 3, 3, 1, data.data(), g);
    const dem::Dem d = dem::read_dem(dir / "tm.tif");
    EXPECT_FALSE(d.georef.crs().epsg().has_value());
    // The same place on Earth through both CRSs (they are the same projection).
    const glm::dvec2 a = d.georef.pixel_to_lonlat(1.5, 1.5), b = g.pixel_to_lonlat(1.5, 1.5);
    EXPECT_NEAR(a.x, b.x, 1e-9);  // ~0.1 mm
    EXPECT_NEAR(a.y, b.y, 1e-9);
}

TEST(RasterWriter, U8ImagesAsPngAndGeoTiff) {
    const fs::path dir = fresh_dir("u8");
    const int w = 4, h = 3;
    std::vector<std::uint8_t> grey(std::size_t(w * h)), rgb(std::size_t(w * h * 3));
    for (std::size_t i = 0; i < grey.size(); ++i) grey[i] = std::uint8_t(i * 20);
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = std::uint8_t(i * 7);

    raster::write_u8_image(dir / "grey.png", w, h, 1, grey.data(), nullptr);
    auto in = OIIO::ImageInput::open((dir / "grey.png").string());
    ASSERT_TRUE(in);
    std::vector<std::uint8_t> back(grey.size());
    ASSERT_TRUE(in->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT8, back.data()));
    EXPECT_EQ(back, grey);

    const geo::Georef g = utm_georef(w, h, true);
    raster::write_u8_image(dir / "rgb.tif", w, h, 3, rgb.data(), &g);
    raster::write_u8_image(dir / "shade.tif", w, h, 1, grey.data(), &g, 0);
    const nlohmann::json j = gdalinfo(dir / "rgb.tif");
    EXPECT_EQ(j["bands"].size(), 3u);
    EXPECT_EQ(j["stac"]["proj:epsg"], 32733);
    const nlohmann::json s = gdalinfo(dir / "shade.tif");
    EXPECT_EQ(s["bands"][0]["noDataValue"], 0.0);
    EXPECT_EQ(s["bands"][0]["type"], "Byte");
}

TEST(RasterWriter, UnknownExtensionsAndEmptyRastersThrow) {
    const fs::path dir = fresh_dir("bad");
    std::vector<float> data(4, 0.0f);
    std::vector<std::uint8_t> px(4 * 5, 0);
    const geo::Georef g = utm_georef(2, 2, true);
    EXPECT_THROW(raster::write_float_raster(dir / "x.png", 2, 2, 1, data.data(), g), InputError);
    EXPECT_THROW(raster::write_u8_image(dir / "x.bmpx", 2, 2, 1, px.data(), nullptr), InputError);
    // 1 to 4 channels (grey, grey + alpha, RGB, RGBA) are pictures; 5 is not.
    EXPECT_THROW(raster::write_u8_image(dir / "x.png", 2, 2, 5, px.data(), nullptr), InputError);
    EXPECT_THROW(raster::write_float_raster(dir / "x.tif", 0, 2, 1, data.data(), g), InputError);
    EXPECT_FALSE(fs::exists(dir / "x.tif"));
}
