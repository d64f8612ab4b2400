// `terrashade render --extent ... --extent-crs EPSG:3857`: a georeferenced extent in another CRS
// is a render target. Its GeoTIFF carries the requested bounds and CRS (gdalinfo as the
// oracle), pixels off the DEM are transparent, and every covered pixel equals the DEM-grid
// render sampled at the same ground point (inverse Web Mercator written out here, bilinear
// between texel centres) within 1% relative.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "tests/cli/cli_support.hpp"
#include "tests/cli/frame_pixels.hpp"

namespace fs = std::filesystem;

namespace {

using ts::cli_test::Result;
using ts::cli_test::run_ts;

// 101 x 101 texels around Grenoble (lon 5.65..5.85, lat 45.10..45.30).
const std::string kRender = "render " + ts::cli_test::kDem + ts::cli_test::kCrop +
                            " --sun-azimuth 135 --sun-elevation 25 --directions 16";
// lon 5.70..5.90, lat 45.15..45.25 in EPSG:3857: the eastern quarter lies off the crop.
constexpr double kX0 = 634521.0975, kY0 = 5645166.9086, kX1 = 656784.9957, kY1 = 5660965.1103;
const std::string kExtent = " --extent 634521.0975,5645166.9086,656784.9957,5660965.1103 --extent-crs EPSG:3857";
// About 1.7 x 1.1 texels per pixel: the extent samples the grid's render (bilinear). Pixels
// smaller than the texels would shade the sun per pixel (core/render/map_pixel_sun.hpp).
constexpr int kW = 60, kH = 45;

struct Image {
    int width = 0, height = 0, channels = 0;
    std::vector<float> px;
};
Image read(const fs::path& path) {
    ts::raster::FloatPixels f = ts::cli_test::read_float_pixels(path);
    Image im;
    im.width = f.width, im.height = f.height, im.channels = f.channels;
    im.px = std::move(f.data);
    return im;
}

nlohmann::json gdalinfo(const fs::path& path) {
    const Result r = ts::cli_test::run("gdalinfo -json " + ts::cli_test::quote(path.string()));
    return r.exit_code == 0 ? nlohmann::json::parse(r.out, nullptr, false) : nlohmann::json();
}

TEST(RenderExtentCli, WebMercatorExtentIsGeoreferencedAndSamplesTheGridRender) {
    const fs::path dir = ts::cli_test::temp_dir("extent");
    const Result grid_exr = run_ts(kRender + " --device cpu --out " + (dir / "grid.exr").string());
    ASSERT_EQ(grid_exr.exit_code, 0) << grid_exr.err;
    const Result grid_tif = run_ts(kRender + " --device cpu --out " + (dir / "grid.tif").string());
    ASSERT_EQ(grid_tif.exit_code, 0) << grid_tif.err;
    const std::string size = " --size " + std::to_string(kW) + "x" + std::to_string(kH);
    const Result ext_exr = run_ts(kRender + kExtent + size + " --out " + (dir / "extent.exr").string());
    ASSERT_EQ(ext_exr.exit_code, 0) << ext_exr.err;
    const Result ext_tif = run_ts(kRender + kExtent + size + " --out " + (dir / "extent.tif").string());
    ASSERT_EQ(ext_tif.exit_code, 0) << ext_tif.err;

    // The GeoTIFF: the requested size, bounds and CRS, RGBA.
    const nlohmann::json info = gdalinfo(dir / "extent.tif");
    ASSERT_TRUE(info.is_object());
    EXPECT_EQ(info["size"][0], kW);
    EXPECT_EQ(info["size"][1], kH);
    EXPECT_EQ(info["bands"].size(), 4u);
    EXPECT_NE(info["coordinateSystem"]["wkt"].get<std::string>().find("\"EPSG\",3857"), std::string::npos);
    const auto& ul = info["cornerCoordinates"]["upperLeft"];
    const auto& lr = info["cornerCoordinates"]["lowerRight"];
    EXPECT_NEAR(ul[0].get<double>(), kX0, 1e-3);
    EXPECT_NEAR(ul[1].get<double>(), kY1, 1e-3);
    EXPECT_NEAR(lr[0].get<double>(), kX1, 1e-3);
    EXPECT_NEAR(lr[1].get<double>(), kY0, 1e-3);

    // The DEM grid's georef (geographic): pixel edge coordinates from lon/lat.
    const nlohmann::json ginfo = gdalinfo(dir / "grid.tif");
    ASSERT_TRUE(ginfo.is_object());
    const std::vector<double> gt = ginfo["geoTransform"].get<std::vector<double>>();
    const Image grid = read(dir / "grid.exr"), ext = read(dir / "extent.exr");
    ASSERT_EQ(ext.width, kW);
    ASSERT_EQ(ext.channels, 4);
    ASSERT_GE(grid.channels, 3);
    auto grid_at = [&](int c, int r, int ch) {
        c = std::clamp(c, 0, grid.width - 1), r = std::clamp(r, 0, grid.height - 1);
        return double(grid.px[(std::size_t(r) * grid.width + c) * grid.channels + ch]);
    };
    const double radius = 6378137.0, deg = 180.0 / std::numbers::pi;
    std::size_t covered = 0, compared = 0, off_dem_opaque = 0;
    double worst = 0;
    for (int j = 0; j < kH; ++j)
        for (int i = 0; i < kW; ++i) {
            const double x = kX0 + (i + 0.5) * (kX1 - kX0) / kW, y = kY1 - (j + 0.5) * (kY1 - kY0) / kH;
            const double lon = x / radius * deg, lat = (2 * std::atan(std::exp(y / radius)) - std::numbers::pi / 2) * deg;
            const double pc = (lon - gt[0]) / gt[1], pr = (lat - gt[3]) / gt[5];  // edge coordinates
            const float* e = &ext.px[(std::size_t(j) * kW + i) * 4];
            const bool on_dem = pc >= 0 && pr >= 0 && pc <= grid.width && pr <= grid.height;
            if (e[3] > 0.5f) ++covered;
            // Away from the crop's edge (half a pixel of the extent), coverage is unambiguous.
            const bool clear = pc > 1 && pc < grid.width - 1 && pr > 1 && pr < grid.height - 1;
            const bool clearly_off = pc > grid.width + 1 || pc < -1 || pr < -1 || pr > grid.height + 1;
            if (clearly_off && e[3] > 0.5f) ++off_dem_opaque;
            if (!clear) continue;
            EXPECT_GT(e[3], 0.5f) << i << "," << j;
            if (!on_dem || e[3] < 0.5f) continue;
            const double cx = pc - 0.5, cy = pr - 0.5;
            const int c0 = int(std::floor(cx)), r0 = int(std::floor(cy));
            const double fx = cx - c0, fy = cy - r0;
            for (int ch = 0; ch < 3; ++ch) {
                const double ref = (grid_at(c0, r0, ch) * (1 - fx) + grid_at(c0 + 1, r0, ch) * fx) * (1 - fy) +
                                   (grid_at(c0, r0 + 1, ch) * (1 - fx) + grid_at(c0 + 1, r0 + 1, ch) * fx) * fy;
                worst = std::max(worst, std::abs(double(e[ch]) - ref) / std::max(std::abs(ref), 1e-6));
            }
            ++compared;
        }
    std::printf("extent %dx%d in EPSG:3857: %zu pixels covered, %zu compared, worst relative %.2e\n", kW, kH,
                covered, compared, worst);
    EXPECT_EQ(off_dem_opaque, 0u);
    EXPECT_GT(compared, std::size_t(kW * kH / 2));
    EXPECT_LT(covered, std::size_t(kW * kH * 9 / 10));  // the eastern quarter is off the crop
    EXPECT_LE(worst, 0.01);
}

TEST(RenderExtentCli, BadExtentsFailBeforeTheWork) {
    const fs::path dir = ts::cli_test::temp_dir("extent_bad");
    const std::string out = " --out " + (dir / "x.png").string();
    for (const std::string bad : {" --extent 1,2,3", " --extent 3,0,1,1", " --extent a,b,c,d",
                                  " --extent 634521,5645166,656784,5660965 --extent-crs EPSG:999999",
                                  " --extent-crs EPSG:3857",
                                  " --extent 0,0,1000,1000 --extent-crs EPSG:3857"}) {
        const Result r = run_ts(kRender + bad + out);
        EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.err;
        EXPECT_FALSE(fs::exists(dir / "x.png")) << bad;
    }
}

}  // namespace
