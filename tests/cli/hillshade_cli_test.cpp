// `terrashade hillshade` against `gdaldem hillshade` (GDAL as a test oracle only).
//  - Projected DEMs (made here with gdalwarp from the shared DEMs): every interior pixel within
//    1 grey level of gdaldem. The only modelled difference is that terrashade uses true ground
//    spacing (CRS units / projection scale factor, |k - 1| < 1e-3 for these CRSs and areas), which
//    moves a value by < 0.3 grey level; with rounding that is <= 1.
//  - Geographic DEMs: gdaldem has one scale for both axes, so it cannot shade them right. The
//    oracle is gdaldem on a thin band of rows whose geotransform is set to the true metric spacing
//    at the band's centre (from GeographicLib geodesics, independent of terrashade's code). Within
//    60 rows the east-west spacing varies by < 4e-4 relative (d cos(lat)/cos(lat) = tan(lat) dlat),
//    < 0.1 grey level, so the tolerance is again 1 grey level.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <GeographicLib/Geodesic.hpp>
#include <gtest/gtest.h>

#include "tests/cli/cli_support.hpp"
#include "tests/cli/frame_pixels.hpp"

namespace fs = std::filesystem;

namespace {

// Runs a shell command (terrashade or a GDAL oracle).
using ts::cli_test::Pixels;
using ts::cli_test::read_pixels;
using ts::cli_test::Result;
using ts::cli_test::kSharedDems;
using ts::cli_test::run;
using ts::cli_test::ts_cmd;

struct Image {
    int width = 0, height = 0, channels = 0;
    std::vector<unsigned char> pixels;
    int at(int c, int r) const { return pixels[std::size_t(r) * std::size_t(width) + std::size_t(c)]; }
};

Image read_image(const fs::path& path) {
    Pixels p = read_pixels(path);
    Image img;
    img.width = p.width;
    img.height = p.height;
    img.channels = p.channels;
    img.pixels = std::move(p.data);
    return img;
}

std::string capture(const std::string& cmd) { return ts::cli_test::run(cmd).out; }

struct Comparison {
    long compared = 0, equal = 0, max_diff = 0, over_one = 0;
    long gdal_only = 0;  // gdaldem has a value, terrashade says nodata
    long ts_only = 0;    // terrashade has a value, gdaldem says nodata
};

// Pixels where both have a value (interior pixels: both leave the border and void rims at 0).
Comparison compare(const Image& ts, const Image& gd) {
    Comparison c;
    for (int r = 0; r < gd.height; ++r)
        for (int col = 0; col < gd.width; ++col) {
            const int a = ts.at(col, r), b = gd.at(col, r);
            if (a == 0 && b == 0) continue;
            if (a == 0) { ++c.gdal_only; continue; }
            if (b == 0) { ++c.ts_only; continue; }
            const long d = std::labs(long(a) - long(b));
            ++c.compared;
            if (d == 0) ++c.equal;
            c.max_diff = std::max(c.max_diff, d);
            if (d > 1) ++c.over_one;
        }
    return c;
}

class HillshadeCli : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = fs::temp_directory_path() / ("ts_hillshade_cli_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    // A projected copy of a shared DEM, made on first use (ctest runs each test in its own
    // process, so only the tests that need one pay for gdalwarp). Modest sizes keep it fast.
    static fs::path projected(const std::string& name) {
        const fs::path out = dir_ / name;
        if (fs::exists(out)) return out;
        std::string cmd;
        if (name == "grenoble_l93.tif") {
            cmd = "gdalwarp -q -overwrite -t_srs EPSG:2154 -tr 200 200 -r bilinear " + kSharedDems + "copernicus_N45E005_grenoble_500px.tif ";
        } else {
            cmd = "gdalwarp -q -overwrite -t_srs EPSG:32637 -tr 120 120 -r bilinear " + kSharedDems + "srtm3_N39E040_1000px.tif ";
        }
        const Result r = run(cmd + out.string());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return out;
    }
    static void TearDownTestSuite() {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    static fs::path p(const std::string& name) { return dir_ / name; }

    static inline fs::path dir_;
};

void expect_matches_gdaldem(const fs::path& dir, const fs::path& dem, const std::string& ts_flags, const std::string& gd_flags,
                            bool exact_mask) {
    const fs::path ts_out = dir / (dem.stem().string() + "_ts.tif");
    const fs::path gd_out = dir / (dem.stem().string() + "_gd.tif");
    const Result gd = run("gdaldem hillshade -q " + gd_flags + " " + dem.string() + " " + gd_out.string());
    ASSERT_EQ(gd.exit_code, 0) << gd.err;
    const Result ts = run(ts_cmd("hillshade " + dem.string() + " --out " + ts_out.string() + " " + ts_flags));
    ASSERT_EQ(ts.exit_code, 0) << ts.err;
    const Image a = read_image(ts_out), b = read_image(gd_out);
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    ASSERT_EQ(a.channels, 1);
    const Comparison c = compare(a, b);
    // Most of the image must be compared, or the test proves nothing.
    EXPECT_GT(c.compared, long(a.width) * long(a.height) / 3) << dem;
    EXPECT_LE(c.max_diff, 1) << dem << ": " << c.over_one << " pixels differ by more than 1";
    // terrashade shades every pixel gdaldem shades; with --no-fill the nodata masks agree exactly
    // (border, voids and the 3x3 rim of voids).
    EXPECT_EQ(c.gdal_only, 0) << dem;
    if (exact_mask) {
        EXPECT_EQ(c.ts_only, 0) << dem;
    }
    std::printf("[ info ] %s: %ld pixels compared, %ld equal, max |diff| %ld, %ld shaded only by terrashade\n",
                dem.filename().c_str(), c.compared, c.equal, c.max_diff, c.ts_only);
}

TEST_F(HillshadeCli, MatchesGdaldemOnLambert93) {
    expect_matches_gdaldem(dir_, projected("grenoble_l93.tif"), "--no-fill --no-edges", "", true);
}

TEST_F(HillshadeCli, MatchesGdaldemOnUtmWithOtherLight) {
    expect_matches_gdaldem(dir_, projected("anatolia_utm37.tif"), "--no-fill --no-edges --azimuth 120 --altitude 30 --z-factor 2",
                           "-az 120 -alt 30 -z 2", true);
}

// The default shades the border and the rims of voids as gdaldem -compute_edges does.
TEST_F(HillshadeCli, EdgesMatchGdaldemComputeEdges) {
    expect_matches_gdaldem(dir_, projected("grenoble_l93.tif"), "--no-fill", "-compute_edges", true);
    expect_matches_gdaldem(dir_, projected("anatolia_utm37.tif"), "--no-fill --azimuth 120 --altitude 30",
                           "-compute_edges -az 120 -alt 30", true);
}

TEST_F(HillshadeCli, FilledVoidsShadeAtLeastWhatGdaldemShades) {
    // gdalwarp leaves nodata outside the source footprint; filling it lets terrashade shade the
    // rim pixels gdaldem leaves empty, but never fewer.
    expect_matches_gdaldem(dir_, projected("grenoble_l93.tif"), "", "", false);
}

// The geographic oracle described at the top of the file.
void expect_geographic_band_matches(const fs::path& dir, const std::string& src, int row0, int rows) {
    const fs::path band = dir / ("band_" + std::to_string(row0) + "_" + fs::path(src).stem().string() + ".tif");
    const fs::path metric = dir / ("metric_" + band.filename().string());
    // The full width: a window wider than the source would be padded with zeros by gdal_translate.
    const std::string src_info = capture("gdalinfo " + kSharedDems + src);
    int src_w = 0, src_h = 0;
    ASSERT_EQ(std::sscanf(src_info.substr(src_info.find("Size is")).c_str(), "Size is %d, %d", &src_w, &src_h), 2);
    ASSERT_EQ(run("gdal_translate -q -srcwin 0 " + std::to_string(row0) + " " + std::to_string(src_w) + " " + std::to_string(rows) +
                      " " + kSharedDems + src + " " + band.string()).exit_code, 0);
    // Read the band's geotransform back from gdalinfo: "Origin = (x,y)" and "Pixel Size = (dx,-dy)".
    const std::string info = capture("gdalinfo " + band.string());
    double x0 = 0, y0 = 0, sx = 0, sy = 0;
    int w = 0, h = 0;
    ASSERT_EQ(std::sscanf(info.substr(info.find("Size is")).c_str(), "Size is %d, %d", &w, &h), 2);
    ASSERT_EQ(std::sscanf(info.substr(info.find("Origin =")).c_str(), "Origin = (%lf,%lf)", &x0, &y0), 2);
    ASSERT_EQ(std::sscanf(info.substr(info.find("Pixel Size =")).c_str(), "Pixel Size = (%lf,%lf)", &sx, &sy), 2);
    const double lat = y0 + sy * h * 0.5, lon = x0 + sx * w * 0.5;
    const auto& geod = GeographicLib::Geodesic::WGS84();
    double dx_m = 0, dy_m = 0;
    geod.Inverse(lat, lon - sx / 2, lat, lon + sx / 2, dx_m);
    geod.Inverse(lat - sy / 2, lon, lat + sy / 2, lon, dy_m);
    dy_m = std::abs(dy_m);
    // Same pixels, metric geotransform (the CRS only names units for gdaldem).
    char ullr[256];
    std::snprintf(ullr, sizeof ullr, "0 %.6f %.6f 0", dy_m * h, dx_m * w);
    ASSERT_EQ(run("gdal_translate -q -a_srs EPSG:32637 -a_ullr " + std::string(ullr) + " " + band.string() + " " + metric.string()).exit_code, 0);
    const fs::path ts_out = dir / ("ts_" + band.filename().string());
    const fs::path gd_out = dir / ("gd_" + band.filename().string());
    ASSERT_EQ(run("gdaldem hillshade -q " + metric.string() + " " + gd_out.string()).exit_code, 0);
    const Result ts = run(ts_cmd("hillshade --no-fill --no-edges " + band.string() + " --out " + ts_out.string()));
    ASSERT_EQ(ts.exit_code, 0) << ts.err;
    const Image a = read_image(ts_out), b = read_image(gd_out);
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    const Comparison c = compare(a, b);
    EXPECT_GT(c.compared, long(w - 2) * long(h - 2) * 9 / 10);
    EXPECT_LE(c.max_diff, 1) << src << " rows " << row0 << ": " << c.over_one << " pixels differ by more than 1";
    EXPECT_EQ(c.gdal_only, 0);
    EXPECT_EQ(c.ts_only, 0);
    std::printf("[ info ] %s rows %d..%d (lat %.3f, dx %.2f m, dy %.2f m): %ld compared, %ld equal, max |diff| %ld\n",
                src.c_str(), row0, row0 + rows, lat, dx_m, dy_m, c.compared, c.equal, c.max_diff);
}

TEST_F(HillshadeCli, GeographicDemUsesTrueMetricSpacing) {
    expect_geographic_band_matches(dir_, "srtm3_N39E040_1000px.tif", 470, 60);
    expect_geographic_band_matches(dir_, "copernicus_N45E005_grenoble_500px.tif", 220, 40);
}

TEST_F(HillshadeCli, WritesGeoreferencedTiffAndPng) {
    const fs::path tif = p("grenoble.tif"), png = p("grenoble.png");
    const std::string dem = kSharedDems + "copernicus_N45E005_grenoble_500px.tif";
    ASSERT_EQ(run(ts_cmd("hillshade " + dem + " --out " + tif.string())).exit_code, 0);
    ASSERT_EQ(run(ts_cmd("hillshade " + dem + " -o " + png.string())).exit_code, 0);
    const Image a = read_image(tif), b = read_image(png);
    ASSERT_EQ(a.width, 500);
    ASSERT_EQ(b.width, 500);
    ASSERT_EQ(b.channels, 1);
    EXPECT_EQ(a.pixels, b.pixels);
    // Same grid as the input, and 0 declared as nodata like gdaldem.
    const std::string in_info = capture("gdalinfo " + dem), out_info = capture("gdalinfo " + tif.string());
    auto line = [](const std::string& info, const std::string& key) {
        const auto at = info.find(key);
        return at == std::string::npos ? std::string("missing ") + key : info.substr(at, info.find('\n', at) - at);
    };
    EXPECT_EQ(line(out_info, "Origin ="), line(in_info, "Origin ="));
    EXPECT_EQ(line(out_info, "Pixel Size ="), line(in_info, "Pixel Size ="));
    EXPECT_NE(out_info.find("ID[\"EPSG\",4326]"), std::string::npos);
    EXPECT_NE(out_info.find("NoData Value=0"), std::string::npos);
}

TEST_F(HillshadeCli, BadFlagsExitTwoWithOneLine) {
    const std::string dem = kSharedDems + "nodata_3x3.tif";
    const fs::path out = p("bad.tif");
    // The unit tests cover every boundary; here one of each kind reaches the user as one line.
    for (const std::string flags : {"--altitude 95", "--azimuth nan", "--z-factor 0", "--altitude abc"}) {
        const Result r = run(ts_cmd("hillshade " + dem + " --out " + out.string() + " " + flags));
        EXPECT_EQ(r.exit_code, 2) << flags;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << flags << ": " << r.err;
        EXPECT_FALSE(fs::exists(out)) << flags;
    }
    const Result ext = run(ts_cmd("hillshade " + dem + " --out " + p("x.jpg").string()));
    EXPECT_EQ(ext.exit_code, 2);
    EXPECT_NE(ext.err.find("x.jpg"), std::string::npos) << ext.err;
    const Result no_out = run(ts_cmd("hillshade " + dem));
    EXPECT_EQ(no_out.exit_code, 2);
}

TEST_F(HillshadeCli, MissingDemLeavesExistingOutputUntouched) {
    const fs::path out = p("keep.tif");
    { std::ofstream(out) << "keep"; }
    const Result r = run(ts_cmd("hillshade " + p("no_such.hgt").string() + " --out " + out.string()));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("no_such.hgt"), std::string::npos) << r.err;
    std::ifstream in(out);
    std::string content;
    in >> content;
    EXPECT_EQ(content, "keep");
}

}  // namespace
