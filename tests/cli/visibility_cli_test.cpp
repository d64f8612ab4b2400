// `terrashade visibility` end to end: outputs exist, carry the input's georeferencing, have the
// promised bands, voids come out NaN, exact agrees with the raymarch reference on a small real
// window, and bad usage exits 2 with one line.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/dem/read_dem.hpp"
#include "tests/cli/cli_support.hpp"
#include "tests/cli/frame_pixels.hpp"

namespace fs = std::filesystem;

namespace {

using ts::cli_test::Pixels;
using ts::cli_test::read_pixels;
using ts::cli_test::read_rgb;
using ts::cli_test::Result;
using ts::cli_test::run_ts;
using ts::cli_test::kSharedDems;

class VisibilityCli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("ts_vis_cli_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

// A 0.1 x 0.1 degree window (121 x 121 texels) of the Gabon SRTM tile: the raymarch reference
// stays quick there.
const std::string kWindow = "visibility " + kSharedDems + "N00E010.hgt --crop 10.45,0.45,10.55,0.55";

}  // namespace

TEST_F(VisibilityCli, WritesGeoreferencedRasters) {
    const fs::path svf = dir_ / "svf.tif", sky = dir_ / "sky.tif", hz = dir_ / "hz.tif", sh = dir_ / "sh.tif";
    const Result r = run_ts(kWindow + " --directions 16 --svf " + svf.string() + " --sky-visible " + sky.string() +
                                    " --horizons " + hz.string() + " --sh " + sh.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto in = ts::dem::read_dem(kSharedDems + "N00E010.hgt");
    const auto out = ts::dem::read_dem(svf);
    ASSERT_GT(out.width, 100);
    // Same CRS and the window's corner on the input's pixel grid (1e-9 degree).
    EXPECT_EQ(out.georef.crs().epsg(), in.georef.crs().epsg());
    const auto corner = out.georef.pixel_to_crs(0, 0);
    const auto px = in.georef.crs_to_pixel(corner);
    EXPECT_NEAR(px.x, std::round(px.x), 1e-6);
    EXPECT_NEAR(px.y, std::round(px.y), 1e-6);
    EXPECT_NEAR(out.georef.transform().dx_col, in.georef.transform().dx_col, 1e-12);
    // svf and sky_visible lie in [0, 1], and svf >= sky_visible everywhere: per azimuth
    // cos^2(sigma) = (1 - sin sigma)(1 + sin sigma) >= 1 - sin sigma for sigma in [0, pi/2].
    const auto s = ts::dem::read_dem(sky);
    for (std::size_t i = 0; i < out.z.size(); ++i) {
        ASSERT_GE(out.z[i], 0.0f);
        ASSERT_LE(out.z[i], 1.0f);
        ASSERT_GE(out.z[i] + 1e-6f, s.z[i]);
    }
    // Band counts: readers here keep band 1 only, so ask the file itself via its size on disk
    // relative to the one-band svf (float32, uncompressed or not, the ratio is >= bands / 2).
    EXPECT_GT(fs::file_size(hz), 8 * fs::file_size(svf));
    EXPECT_GT(fs::file_size(sh), 8 * fs::file_size(svf));
}

// Horizon bands go clockwise from north (the user's azimuths), not in the sweep's order
// (east, counter-clockwise): band 1 faces north, band 5 east, band 13 west for D = 16.
TEST_F(VisibilityCli, HorizonBandsGoClockwiseFromNorth) {
    const fs::path hz = dir_ / "hz_order.tif";
    ASSERT_EQ(run_ts(kWindow + " --directions 16 --horizons " + hz.string()).exit_code, 0);
    const Result info = ts::cli_test::run("gdalinfo " + hz.string());
    ASSERT_EQ(info.exit_code, 0) << info.err;
    for (int band = 1; band <= 16; ++band) {
        char want[96];
        std::snprintf(want, sizeof want, "toward azimuth %g deg clockwise from north", 22.5 * (band - 1));
        const auto at = info.out.find("Band " + std::to_string(band) + " ");
        ASSERT_NE(at, std::string::npos) << band;
        const auto next = info.out.find("Band " + std::to_string(band + 1) + " ", at);
        EXPECT_NE(info.out.substr(at, next - at).find(want), std::string::npos) << "band " << band << ": " << want;
    }
    // The values follow the labels: a receiver on the west edge sees no terrain to the west
    // (horizon 0 exactly) but does to the east.
    auto column0 = [&](int band) {
        const fs::path one = dir_ / ("hz_band" + std::to_string(band) + ".tif");
        EXPECT_EQ(ts::cli_test::run("gdal_translate -q -b " + std::to_string(band) + " " + hz.string() + " " + one.string()).exit_code, 0);
        const auto d = ts::dem::read_dem(one);
        std::vector<float> col;
        for (int r = 0; r < d.height; ++r) col.push_back(d.at(0, r));
        return col;
    };
    int west_zero = 0, east_zero = 0;
    for (float v : column0(13)) west_zero += v == 0.0f;
    const std::vector<float> east = column0(5);
    for (float v : east) east_zero += v == 0.0f;
    EXPECT_EQ(west_zero, 121);
    EXPECT_LT(east_zero, 121 / 2);
}

TEST_F(VisibilityCli, ExactAgreesWithRaymarchOnRealWindow) {
    const fs::path a = dir_ / "exact.tif", b = dir_ / "ray.tif";
    ASSERT_EQ(run_ts(kWindow + " --directions 16 --method exact --svf " + a.string()).exit_code, 0);
    ASSERT_EQ(run_ts(kWindow + " --directions 16 --method raymarch --svf " + b.string()).exit_code, 0);
    const auto ea = ts::dem::read_dem(a), eb = ts::dem::read_dem(b);
    double se = 0;
    int n = 0;
    for (int r = 1; r + 1 < ea.height; ++r)
        for (int c = 1; c + 1 < ea.width; ++c) se += std::pow(ea.at(c, r) - eb.at(c, r), 2), ++n;
    // Same azimuths, so only the horizon error counts: docs/visibility.md measures ~1e-3 rms
    // on such windows; 3e-3 leaves room, a broken method is off by 1e-2 or more.
    EXPECT_LT(std::sqrt(se / n), 3e-3);
}

TEST_F(VisibilityCli, PngQuickLookIsTheFloatRasterStretched) {
    const fs::path tif = dir_ / "svf.tif", png = dir_ / "svf.png";
    ASSERT_EQ(run_ts(kWindow + " --directions 8 --svf " + tif.string()).exit_code, 0);
    const Result r = run_ts(kWindow + " --directions 8 --svf " + png.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // The stretch is printed: "...: grey 1..255 = LO..HI (the 1st to 99th percentile ...".
    const auto at = r.out.find("grey 1..255 = ");
    ASSERT_NE(at, std::string::npos) << r.out;
    double lo = 0, hi = 0;
    ASSERT_EQ(std::sscanf(r.out.c_str() + at, "grey 1..255 = %lf..%lf", &lo, &hi), 2) << r.out;
    ASSERT_LT(lo, hi);
    const auto ref = ts::dem::read_dem(tif);
    const Pixels grey_png = read_pixels(png);
    ASSERT_EQ(grey_png.width, ref.width) << png;
    ASSERT_EQ(grey_png.channels, 1);
    const std::vector<unsigned char>& grey = grey_png.data;
    // Grey g = 1 + 254 (svf - lo) / (hi - lo), clamped: within half a level (lo and hi are
    // printed to 4 decimals, hence the allowance).
    long white = 0, valid = 0;
    int darkest = 255;
    for (int row = 0; row < ref.height; ++row)
        for (int c = 0; c < ref.width; ++c) {
            const int g = grey[std::size_t(row) * ref.width + c];
            const float v = ref.at(c, row);
            if (std::isnan(v)) {
                ASSERT_EQ(g, 0);  // void
                continue;
            }
            const double want = 1 + 254 * std::clamp((v - lo) / (hi - lo), 0.0, 1.0);
            ASSERT_NEAR(g, want, 0.5 + 254 * 1e-4 / (hi - lo) + 1e-6) << c << "," << row << " svf " << v;
            ++valid, white += g == 255, darkest = std::min(darkest, g);
        }
    // The whole grey range is used, and few pixels are pure white (the 1% above the 99th percentile).
    EXPECT_LE(darkest, 2);
    EXPECT_LT(double(white) / double(valid), 0.02);

    // Its legend beside it: the ramp from grey 1 (left) to 255 (right) under a title line.
    const fs::path legend = dir_ / "svf_legend.png";
    EXPECT_NE(r.out.find("legend in " + legend.string()), std::string::npos) << r.out;
    int lw = 0, lh = 0;
    const std::vector<unsigned char> rgb = read_rgb(legend, lw, lh);
    ASSERT_FALSE(rgb.empty()) << legend;
    EXPECT_GE(lw, 200);
    // The bar's row: the first row below the title whose middle pixel is mid-grey.
    int bar = -1;
    for (int y = 0; y < lh && bar < 0; ++y)
        if (const int g = rgb[(std::size_t(y) * std::size_t(lw) + std::size_t(lw / 2)) * 3]; g > 100 && g < 160) bar = y;
    ASSERT_GE(bar, 0);
    EXPECT_LE(rgb[(std::size_t(bar) * std::size_t(lw) + 4) * 3], 3);
    EXPECT_GE(rgb[(std::size_t(bar) * std::size_t(lw) + std::size_t(lw - 5)) * 3], 253);
}

TEST_F(VisibilityCli, VoidReceiverIsNaN) {
    // nodata_3x3.tif: a 3x3 grid whose lower-right 2x2 block is nodata (9999).
    const fs::path svf = dir_ / "svf.tif";
    const Result r =
        run_ts("visibility " + kSharedDems + "nodata_3x3.tif --directions 8 --no-curvature --svf " + svf.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto out = ts::dem::read_dem(svf);
    ASSERT_EQ(out.width, 3);
    EXPECT_TRUE(std::isnan(out.at(1, 1)) || out.is_void(1, 1));
    EXPECT_TRUE(std::isnan(out.at(2, 2)) || out.is_void(2, 2));
    EXPECT_FALSE(std::isnan(out.at(0, 0)));
}

TEST_F(VisibilityCli, BadUsageExitsTwoWithOneLine) {
    for (const std::string& args :
         {"visibility " + kSharedDems + "N00E010.hgt --method nonsense --svf x.tif",
          "visibility " + kSharedDems + "N00E010.hgt --directions 0 --svf x.tif", "visibility " + kSharedDems + "N00E010.hgt",
          std::string("visibility /nonexistent.hgt --svf x.tif")}) {
        const Result r = run_ts(args);
        EXPECT_EQ(r.exit_code, 2) << args;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    }
}
