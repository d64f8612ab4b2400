// core/raster/float_cog_writer: a multi-band float COG reads back bit for bit (libtiff, and
// terrashade's DEM reader for one band), each overview is the NaN-aware 2x2 mean of the level
// above, the tiles lie band by band in each IFD with the smallest overview first; gdalinfo
// (the oracle, never linked) sees the descriptions, units, NaN nodata, overviews and the COG
// layout, and GDAL's validate_cloud_optimized_geotiff.py (python3-gdal) passes it with no error
// or warning.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tiffio.h>

#include "core/dem/read_dem.hpp"
#include "core/raster/cog_writer.hpp"
#include "core/raster/float_cog_writer.hpp"
#include "core/raster/tiff_file.hpp"
#include "tests/support/scratch_dir.hpp"

namespace ts::raster::float_cog_test {
namespace {
namespace fs = std::filesystem;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

geo::Georef utm_georef(int w, int h) {
    return geo::Georef(w, h, {500020.0, 30.0, 0, 9990000.0, 0, -30.0}, geo::Crs::from_epsg(32633), true);
}

// stdout and stderr of a shell command (GDAL's tools are the oracle; they print warnings on
// stderr).
std::string run(const std::string& cmd, int* exit_code = nullptr) {
    FILE* pipe = popen((cmd + " 2>&1").c_str(), "r");
    std::string out;
    std::array<char, 4096> buf{};
    while (pipe && fgets(buf.data(), int(buf.size()), pipe)) out += buf.data();
    const int status = pipe ? pclose(pipe) : -1;
    if (exit_code) *exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return out;
}

// A test raster: smooth ramps per band, a void 2x2 block, blocks with one to three voids, an
// infinity (not finite: left out of the means as a void), and a void last column.
std::vector<float> sample_bands(int w, int h, int bands) {
    // The voids and the infinity below sit at rows and columns up to 51.
    if (w < 52 || h < 52) throw std::invalid_argument("sample_bands: at least 52 x 52 texels");
    std::vector<float> v(std::size_t(w) * std::size_t(h) * std::size_t(bands));
    for (int b = 0; b < bands; ++b)
        for (int r = 0; r < h; ++r)
            for (int c = 0; c < w; ++c)
                v[(std::size_t(b) * h + r) * w + c] = float(b) * 1000.0f + float(c) * 0.37f - float(r) * 1.3f +
                                                      1e-3f * float((c * 7 + r * 13) % 11);
    auto at = [&](int b, int r, int c) -> float& { return v[(std::size_t(b) * h + r) * w + c]; };
    for (int b = 0; b < bands; ++b) {
        at(b, 10, 10) = at(b, 10, 11) = at(b, 11, 10) = at(b, 11, 11) = kNaN;  // a void block
        at(b, 20, 20) = kNaN;                                                  // 3 of 4 finite
        at(b, 30, 30) = at(b, 31, 31) = kNaN;                                  // 2 of 4
        at(b, 40, 40) = at(b, 40, 41) = at(b, 41, 40) = kNaN;                  // 1 of 4
        at(b, 50, 50) = std::numeric_limits<float>::infinity();
        for (int r = 0; r < h; ++r) at(b, r, w - 1) = kNaN;
    }
    return v;
}

// One IFD read through libtiff: band-sequential planes, and where its tiles lie.
struct Level {
    int width = 0, height = 0;
    std::vector<float> px;
    std::vector<std::uint64_t> tile_offsets, tile_sizes;  // in TIFF (band, row, column) order
    std::uint64_t ifd_offset = 0;
};

std::vector<Level> read_levels(const fs::path& p, int bands) {
    register_tiff_tags();
    std::vector<Level> out;
    TIFF* tif = TIFFOpen(p.c_str(), "r");
    if (!tif) return out;
    do {
        Level l;
        std::uint32_t w = 0, h = 0, tw = 0, th = 0;
        std::uint16_t planar = 0, spp = 0;
        TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &w);
        TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &h);
        TIFFGetField(tif, TIFFTAG_TILEWIDTH, &tw);
        TIFFGetField(tif, TIFFTAG_TILELENGTH, &th);
        TIFFGetField(tif, TIFFTAG_PLANARCONFIG, &planar);
        TIFFGetField(tif, TIFFTAG_SAMPLESPERPIXEL, &spp);
        EXPECT_EQ(planar, PLANARCONFIG_SEPARATE);
        EXPECT_EQ(spp, bands);
        l.width = int(w), l.height = int(h), l.ifd_offset = TIFFCurrentDirOffset(tif);
        l.px.resize(std::size_t(w) * h * std::size_t(bands));
        std::vector<float> tile(std::size_t(tw) * th);
        for (int b = 0; b < bands; ++b)
            for (std::uint32_t r0 = 0; r0 < h; r0 += th)
                for (std::uint32_t c0 = 0; c0 < w; c0 += tw) {
                    EXPECT_GT(TIFFReadTile(tif, tile.data(), c0, r0, 0, tsample_t(b)), 0);
                    for (std::uint32_t r = r0; r < std::min(h, r0 + th); ++r)
                        std::memcpy(&l.px[(std::size_t(b) * h + r) * w + c0], &tile[std::size_t(r - r0) * tw],
                                    std::min(tw, w - c0) * sizeof(float));
                }
        for (ttile_t t = 0; t < TIFFNumberOfTiles(tif); ++t) {
            l.tile_offsets.push_back(TIFFGetStrileOffset(tif, t));
            l.tile_sizes.push_back(TIFFGetStrileByteCount(tif, t));
        }
        out.push_back(std::move(l));
    } while (TIFFReadDirectory(tif));
    TIFFClose(tif);
    return out;
}

TEST(FloatCogWriter, BandsRoundTripBitForBitAndOverviewsAreNanAwareMeans) {
    const int w = 600, h = 300, bands = 5;
    const std::vector<float> data = sample_bands(w, h, bands);
    const fs::path file = test::fresh_dir("float_cog") / "bands.tif";
    write_float_cog(file, w, h, bands, data.data(), utm_georef(w, h));
    const auto levels = read_levels(file, bands);
    const auto sizes = cog_overview_sizes(w, h);
    ASSERT_EQ(sizes.size(), 2u);  // 300x150, 150x75
    ASSERT_EQ(levels.size(), 1 + sizes.size());
    ASSERT_EQ(levels[0].px.size(), data.size());
    EXPECT_EQ(std::memcmp(levels[0].px.data(), data.data(), data.size() * sizeof(float)), 0);

    for (std::size_t i = 1; i < levels.size(); ++i) {
        const Level &up = levels[i - 1], &l = levels[i];
        ASSERT_EQ(l.width, sizes[i - 1].first);
        ASSERT_EQ(l.height, sizes[i - 1].second);
        int voids = 0;
        for (int b = 0; b < bands; ++b)
            for (int r = 0; r < l.height; ++r)
                for (int c = 0; c < l.width; ++c) {
                    double sum = 0;
                    int n = 0;
                    for (int dr = 0; dr < 2; ++dr)
                        for (int dc = 0; dc < 2; ++dc) {
                            const int sr = 2 * r + dr, sc = 2 * c + dc;
                            if (sr >= up.height || sc >= up.width) continue;
                            const float v = up.px[(std::size_t(b) * up.height + sr) * up.width + sc];
                            if (std::isfinite(v)) sum += v, ++n;
                        }
                    const float got = l.px[(std::size_t(b) * l.height + r) * l.width + c];
                    if (n == 0) {
                        EXPECT_TRUE(std::isnan(got)) << "overview " << i << " band " << b << " " << r << "," << c;
                        ++voids;
                    } else {
                        ASSERT_NEAR(got, sum / n, 1e-6 * std::max(1.0, std::abs(sum / n)))
                            << "overview " << i << " band " << b << " " << r << "," << c;
                    }
                }
        // The void 2x2 block, once per band (the void last column meets a finite one).
        if (i == 1) {
            EXPECT_EQ(voids, bands);
        }
    }
    // The 1-of-4 block's mean is that one value; the infinity's block the mean of the other 3.
    const Level& o1 = levels[1];
    EXPECT_EQ(o1.px[std::size_t(20) * o1.width + 20], data[std::size_t(41) * w + 41]);
    const double finite3 = (double(data[std::size_t(50) * w + 51]) + data[std::size_t(51) * w + 50] +
                            data[std::size_t(51) * w + 51]) / 3;
    EXPECT_NEAR(o1.px[std::size_t(25) * o1.width + 25], finite3, 1e-4);

    // Layout: every IFD before any tile; within an IFD the tiles of band 1 row-major, then band
    // 2 ...; the smallest overview's tiles first; each tile behind its size and before a copy of
    // its last 4 bytes.
    const std::string b = test::slurp(file);
    for (const Level& l : levels) {
        ASSERT_EQ(l.tile_offsets.size(), std::size_t(bands) * ((l.width + 255) / 256) * ((l.height + 255) / 256));
        for (std::size_t t = 0; t < l.tile_offsets.size(); ++t) {
            const std::uint64_t off = l.tile_offsets[t], n = l.tile_sizes[t];
            EXPECT_GT(off, levels.back().ifd_offset);
            if (t) {
                EXPECT_EQ(off, l.tile_offsets[t - 1] + l.tile_sizes[t - 1] + 8) << "tile " << t;
            }
            std::uint32_t leader = 0;
            std::memcpy(&leader, b.data() + off - 4, 4);
            EXPECT_EQ(leader, n);
            EXPECT_EQ(b.compare(off + n - 4, 4, b, off + n, 4), 0);
        }
    }
    for (std::size_t i = 0; i + 1 < levels.size(); ++i)
        EXPECT_EQ(levels[i].tile_offsets.front(),
                  levels[i + 1].tile_offsets.back() + levels[i + 1].tile_sizes.back() + 8);
    EXPECT_EQ(levels[0].tile_offsets.back() + levels[0].tile_sizes.back() + 4, b.size());
}

TEST(FloatCogWriter, OneBandReadsBackThroughTheDemReader) {
    const int w = 300, h = 270;
    std::vector<float> data = sample_bands(w, h, 1);
    data[std::size_t(50) * w + 50] = 123.5f;  // the DEM reader takes any non-finite height as a void
    const fs::path file = test::fresh_dir("float_cog_dem") / "dem.tif";
    write_float_cog(file, w, h, 1, data.data(), utm_georef(w, h));
    const dem::Dem d = dem::read_dem(file);
    ASSERT_EQ(d.width, w);
    ASSERT_EQ(d.height, h);
    EXPECT_EQ(d.georef.crs().epsg(), 32633);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            const float want = data[std::size_t(r) * w + c];
            if (std::isnan(want))
                EXPECT_TRUE(d.is_void(c, r)) << r << "," << c;
            else
                EXPECT_EQ(std::memcmp(&d.z[std::size_t(r) * w + c], &want, sizeof want), 0) << r << "," << c;
        }
}

TEST(FloatCogWriter, GdalSeesDescriptionsUnitsNodataOverviewsAndAValidCog) {
    const int w = 600, h = 300, bands = 5;
    const std::vector<float> data = sample_bands(w, h, bands);
    const fs::path file = test::fresh_dir("float_cog_gdal") / "described.tif";
    const std::vector<std::string> names = {"global irradiation 2024 (kWh/m2)", "beam & <direct>", "diffuse",
                                            "reflected", "hours of direct sun 2024 (h)"};
    const std::vector<std::string> units = {"kWh/m2", "kWh/m2", "kWh/m2", "kWh/m2", "h"};
    write_float_cog(file, w, h, bands, data.data(), utm_georef(w, h), names, units);

    int code = -1;
    const std::string info = run("gdalinfo -json -stats '" + file.string() + "'", &code);
    ASSERT_EQ(code, 0) << info;
    const auto j = nlohmann::json::parse(info.substr(info.find('{')));
    EXPECT_EQ(j["metadata"]["IMAGE_STRUCTURE"]["LAYOUT"], "COG");
    EXPECT_EQ(j["metadata"]["IMAGE_STRUCTURE"]["INTERLEAVE"], "BAND");
    EXPECT_EQ(j["metadata"]["IMAGE_STRUCTURE"]["COMPRESSION"], "DEFLATE");
    EXPECT_EQ(j["stac"]["proj:epsg"], 32633);
    ASSERT_EQ(j["bands"].size(), std::size_t(bands));
    for (int b = 0; b < bands; ++b) {
        const auto& band = j["bands"][b];
        EXPECT_EQ(band["type"], "Float32");
        EXPECT_EQ(band["description"], names[std::size_t(b)]);
        EXPECT_EQ(band["unit"], units[std::size_t(b)]);
        EXPECT_EQ(band["noDataValue"], "NaN");
        EXPECT_EQ(band["block"][0], 256);
        ASSERT_EQ(band["overviews"].size(), 2u);
        EXPECT_EQ(band["overviews"][0]["size"][0], 300);
        EXPECT_EQ(band["overviews"][0]["size"][1], 150);
        EXPECT_EQ(band["overviews"][1]["size"][0], 150);
        EXPECT_EQ(band["overviews"][1]["size"][1], 75);
        // GDAL decodes each plane into its band (gdalinfo prints 3 decimals).
        EXPECT_NEAR(band["minimum"].get<double>(), double(data[(std::size_t(b) * h + h - 1) * w]), 1e-3);
    }

    const std::string valid = run("/usr/bin/python3 -m osgeo_utils.samples.validate_cloud_optimized_geotiff "
                                  "--full-check=yes '" + file.string() + "'", &code);
    EXPECT_EQ(code, 0) << valid;
    EXPECT_NE(valid.find("is a valid cloud optimized GeoTIFF"), std::string::npos) << valid;
    // Printed only when there was neither an error nor a warning.
    EXPECT_NE(valid.find("The size of all IFD headers is"), std::string::npos) << valid;
    EXPECT_EQ(valid.find("warning"), std::string::npos) << valid;
}

// insolation --by day writes up to 2000 bands: 1999 ExtraSamples and 4000 metadata items in
// the main IFD, 2000 planes of tiles; GDAL reads the last band's name, unit and pixels, and the
// validator still passes. (Small: each band is still one 256-px tile to encode and check.)
TEST(FloatCogWriter, TwoThousandBandsStayReadableAndValid) {
    const int w = 8, h = 8, bands = 2000;
    std::vector<float> data(std::size_t(w) * h * bands);
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = float(i % 9973) * 0.25f;
    std::vector<std::string> names, units(std::size_t(bands), "h");
    for (int b = 0; b < bands; ++b) names.push_back("band " + std::to_string(b + 1));
    const fs::path file = test::fresh_dir("float_cog_many") / "many.tif";
    write_float_cog(file, w, h, bands, data.data(), utm_georef(w, h), names, units);

    int code = -1;
    const std::string info = run("gdalinfo -json '" + file.string() + "'", &code);
    ASSERT_EQ(code, 0) << info.substr(0, 2000);
    const auto j = nlohmann::json::parse(info.substr(info.find('{')));
    ASSERT_EQ(j["bands"].size(), std::size_t(bands));
    EXPECT_EQ(j["bands"][bands - 1]["description"], "band 2000");
    EXPECT_EQ(j["bands"][bands - 1]["unit"], "h");
    const std::string pixel = run("gdallocationinfo -valonly -b 2000 '" + file.string() + "' 7 2", &code);
    EXPECT_EQ(code, 0) << pixel;
    EXPECT_EQ(std::stod(pixel), double(data[(std::size_t(bands - 1) * h + 2) * w + 7])) << pixel;
    const std::string valid = run("/usr/bin/python3 -m osgeo_utils.samples.validate_cloud_optimized_geotiff "
                                  "--full-check=yes '" + file.string() + "'", &code);
    EXPECT_EQ(code, 0) << valid;
    EXPECT_NE(valid.find("The size of all IFD headers is"), std::string::npos) << valid;
}

// A float COG past 3 GiB of tiles is a BigTIFF (too large to write here): lay_out_as_cog on a
// small BigTIFF written by libtiff as write_float_cog does (two band-separate levels) gives a
// BigTIFF COG that reads back the same and that GDAL's validator passes.
TEST(FloatCogWriter, BigTiffLaysOutAsACogToo) {
    const int w = 300, h = 64, bands = 2;
    const std::vector<float> data = sample_bands(w, h, bands);
    const fs::path file = test::fresh_dir("float_cog_big") / "big.tif";
    {
        TiffFile tiff(file, "w8l");
        TIFF* tif = tiff.get();
        for (int level = 0; level < 2; ++level) {
            const int lw = level ? w / 2 : w, lh = level ? h / 2 : h;
            TIFFSetField(tif, TIFFTAG_SUBFILETYPE, level ? FILETYPE_REDUCEDIMAGE : 0);
            TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, std::uint32_t(lw));
            TIFFSetField(tif, TIFFTAG_IMAGELENGTH, std::uint32_t(lh));
            TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, 32);
            TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_IEEEFP);
            TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, bands);
            TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_SEPARATE);
            TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
            std::uint16_t extra = EXTRASAMPLE_UNSPECIFIED;
            TIFFSetField(tif, TIFFTAG_EXTRASAMPLES, 1, &extra);
            TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
            TIFFSetField(tif, TIFFTAG_PREDICTOR, PREDICTOR_FLOATINGPOINT);
            TIFFSetField(tif, TIFFTAG_TILEWIDTH, 256u);
            TIFFSetField(tif, TIFFTAG_TILELENGTH, 256u);
            std::vector<float> tile(256 * 256);
            for (int b = 0; b < bands; ++b)
                for (int c0 = 0; c0 < lw; c0 += 256) {
                    std::fill(tile.begin(), tile.end(), kNaN);
                    for (int r = 0; r < lh; ++r)
                        for (int c = c0; c < std::min(lw, c0 + 256); ++c)
                            tile[std::size_t(r) * 256 + std::size_t(c - c0)] =
                                level ? float(r * c) : data[(std::size_t(b) * h + r) * w + c];
                    const ttile_t t = TIFFComputeTile(tif, std::uint32_t(c0), 0, 0, tsample_t(b));
                    ASSERT_GT(TIFFWriteEncodedTile(tif, t, tile.data(), tmsize_t(tile.size() * sizeof(float))), 0);
                }
            ASSERT_TRUE(TIFFWriteDirectory(tif));
        }
        tiff.close();
    }
    lay_out_as_cog(file, file.string());
    const std::string b = test::slurp(file);
    ASSERT_GT(b.size(), 16u);
    EXPECT_EQ(b[2], 43) << "still a BigTIFF";
    const auto levels = read_levels(file, bands);
    ASSERT_EQ(levels.size(), 2u);
    EXPECT_EQ(std::memcmp(levels[0].px.data(), data.data(), data.size() * sizeof(float)), 0);
    EXPECT_EQ(levels[1].px[std::size_t(3) * (w / 2) + 5], 15.0f);
    EXPECT_LT(levels[1].tile_offsets.back(), levels[0].tile_offsets.front());
    int code = -1;
    const std::string valid = run("/usr/bin/python3 -m osgeo_utils.samples.validate_cloud_optimized_geotiff "
                                  "--full-check=yes '" + file.string() + "'", &code);
    EXPECT_EQ(code, 0) << valid;
    EXPECT_NE(valid.find("The size of all IFD headers is"), std::string::npos) << valid;
}

}  // namespace
}  // namespace ts::raster::float_cog_test
