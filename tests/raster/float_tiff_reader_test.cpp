// core/raster/float_tiff_reader: what write_float_cog (tiled, bands separate, with overviews and
// an ImageDescription) and write_float_raster (the plain float GeoTIFF) write reads back bit for
// bit, NaN included, with the georeferencing; an 8-bit picture, a file past the value cap and a
// file that is no TIFF are refused with the file named.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/raster/float_cog_writer.hpp"
#include "core/raster/float_tiff_reader.hpp"
#include "core/raster/raster_writer.hpp"
#include "core/util/error.hpp"
#include "tests/support/scratch_dir.hpp"

namespace ts::raster::float_tiff_reader_test {
namespace {

// 300 x 290 x 3 bands (more than one 256-px tile each way, edge tiles partial), voids included.
std::vector<float> bands_of(int w, int h, int bands) {
    std::vector<float> v(std::size_t(w) * std::size_t(h) * std::size_t(bands));
    for (std::size_t k = 0; k < v.size(); ++k)
        v[k] = k % 97 == 0 ? std::numeric_limits<float>::quiet_NaN() : float(std::sin(0.001 * double(k)) * 1e3);
    return v;
}

geo::Georef lonlat_georef(int w, int h) {
    return geo::Georef(w, h, {5.5, 1.0 / 500, 0, 45.4, 0, -1.0 / 500}, geo::Crs::wgs84(), true);
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(FloatTiffReader, ReadsACogBackBitForBitWithItsDescription) {
    const auto dir = ts::test::fresh_dir("float_tiff_reader_cog");
    const int w = 300, h = 290, bands = 3;
    const std::vector<float> values = bands_of(w, h, bands);
    const auto path = dir / "map.tif";
    write_float_cog(path, w, h, bands, values.data(), lonlat_georef(w, h), {"a", "b", "c"}, {}, "{\"shard\":\"1/4\"}");
    const FloatTiff t = read_float_tiff(path, std::size_t(1) << 30);
    EXPECT_EQ(t.width, w);
    EXPECT_EQ(t.height, h);
    EXPECT_EQ(t.bands, bands);
    EXPECT_TRUE(same_bits(t.values, values));
    EXPECT_EQ(t.image_description, "{\"shard\":\"1/4\"}");
    EXPECT_DOUBLE_EQ(t.georef.transform().x0, 5.5);
    EXPECT_DOUBLE_EQ(t.georef.transform().y0, 45.4);
    EXPECT_DOUBLE_EQ(t.georef.transform().dx_col, 1.0 / 500);
}

TEST(FloatTiffReader, ReadsThePlainFloatGeoTiffBackBitForBit) {
    const auto dir = ts::test::fresh_dir("float_tiff_reader_plain");
    const int w = 300, h = 290, bands = 2;
    const std::vector<float> values = bands_of(w, h, bands);
    const auto path = dir / "plain.tif";
    write_float_raster(path, w, h, bands, values.data(), lonlat_georef(w, h));
    const FloatTiff t = read_float_tiff(path, std::size_t(1) << 30);
    EXPECT_EQ(t.bands, bands);
    EXPECT_TRUE(same_bits(t.values, values));
    EXPECT_EQ(t.image_description, "");
}

TEST(FloatTiffReader, RefusesWhatItCannotHoldOrRead) {
    const auto dir = ts::test::fresh_dir("float_tiff_reader_bad");
    const std::vector<float> values = bands_of(40, 30, 1);
    write_float_raster(dir / "f.tif", 40, 30, 1, values.data(), lonlat_georef(40, 30));
    EXPECT_THROW(read_float_tiff(dir / "f.tif", 1000), InputError);  // 1200 values
    const std::vector<std::uint8_t> grey(40 * 30, 7);
    const geo::Georef g = lonlat_georef(40, 30);
    write_u8_image(dir / "grey.tif", 40, 30, 1, grey.data(), &g);
    try {
        read_float_tiff(dir / "grey.tif", 1u << 20);
        FAIL() << "an 8-bit picture was read as floats";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("grey.tif"), std::string::npos) << e.what();
    }
    {
        std::FILE* f = std::fopen((dir / "junk.tif").c_str(), "wb");
        std::fputs("not a tiff at all", f);
        std::fclose(f);
    }
    EXPECT_THROW(read_float_tiff(dir / "junk.tif", 1u << 20), InputError);
}

}  // namespace
}  // namespace ts::raster::float_tiff_reader_test
