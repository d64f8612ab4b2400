// `terrashade render`, `relight` and `bench relight` end to end on a 100x100 crop of the shipped
// Grenoble DEM: outputs exist with the right size and georeferencing, bad input exits 2 with
// one line, and nothing is left behind when a command fails.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "tests/cli/frame_pixels.hpp"

namespace ts::cli_test {
namespace {

// Width and height from a PNG's IHDR chunk (big-endian at bytes 16..23).
std::pair<int, int> png_size(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    unsigned char b[24] = {};
    in.read(reinterpret_cast<char*>(b), 24);
    auto be = [&](int o) { return int(b[o]) << 24 | int(b[o + 1]) << 16 | int(b[o + 2]) << 8 | int(b[o + 3]); };
    return {be(16), be(20)};
}

TEST(RenderCli, MapPngHasTheDemSize) {
    const auto dir = temp_dir("render_map");
    const auto out = dir / "map.png";
    const Result r = run(ts_cmd("render " + quote(kDem) + kCrop + " --time 2025-06-21T10:00:00+02:00 --out " +
                                quote(out.string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("sun: azimuth"), std::string::npos);
    ASSERT_TRUE(std::filesystem::exists(out));
    EXPECT_EQ(png_size(out), std::make_pair(101, 101));
}

TEST(RenderCli, MapTifIsGeoreferencedAndSunVisibilityInRange) {
    const auto dir = temp_dir("render_tif");
    const auto out = dir / "map.tif", vis = dir / "sun.tif";
    const Result r = run(ts_cmd("render " + quote(kDem) + kCrop +
                                " --sun-azimuth 135 --sun-elevation 12 --sky overcast --exposure 13 --out " +
                                quote(out.string()) + " --sun-visibility " + quote(vis.string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Result info = run("gdalinfo -json " + quote(out.string()));
    ASSERT_EQ(info.exit_code, 0) << info.err;
    const auto j = nlohmann::json::parse(info.out);
    EXPECT_EQ(j["size"][0], 101);
    EXPECT_EQ(j["bands"].size(), 3u);
    EXPECT_NE(j["coordinateSystem"]["wkt"].get<std::string>().find("WGS 84"), std::string::npos);
    const Result stats = run("gdalinfo -json -stats " + quote(vis.string()));
    ASSERT_EQ(stats.exit_code, 0) << stats.err;
    const auto s = nlohmann::json::parse(stats.out)["bands"][0];
    EXPECT_GE(s["minimum"].get<double>(), 0.0);
    EXPECT_LE(s["maximum"].get<double>(), 1.0);
    // A low sun over the Alps: some texels in shadow, some lit.
    EXPECT_LT(s["minimum"].get<double>(), 0.01);
    EXPECT_GT(s["maximum"].get<double>(), 0.99);
}

// A map .tif is a Cloud-Optimized GeoTIFF: gdalinfo reports the COG layout, 256-px blocks,
// overviews and the DEM's CRS and corners; GDAL's validator (python3-gdal) accepts it with its
// full check of the tile leaders and trailers; its pixels are the PNG's.
TEST(RenderCli, MapTifIsACloudOptimizedGeoTiffWithOverviews) {
    const auto dir = temp_dir("render_cog");
    const auto tif = dir / "map.tif", png = dir / "map.png";
    const std::string args = "render " + quote(kDem) + " --directions 8 --sun-azimuth 135 --sun-elevation 30 --out ";
    ASSERT_EQ(run(ts_cmd(args + quote(tif.string()))).exit_code, 0);
    ASSERT_EQ(run(ts_cmd(args + quote(png.string()))).exit_code, 0);
    const Result info = run("gdalinfo -json " + quote(tif.string()));
    ASSERT_EQ(info.exit_code, 0) << info.err;
    const auto j = nlohmann::json::parse(info.out);
    EXPECT_EQ(j["metadata"]["IMAGE_STRUCTURE"]["LAYOUT"], "COG") << info.out.substr(0, 2000);
    EXPECT_EQ(j["metadata"]["IMAGE_STRUCTURE"]["COMPRESSION"], "DEFLATE");
    EXPECT_EQ(j["size"][0], 500);
    EXPECT_EQ(j["size"][1], 500);
    ASSERT_EQ(j["bands"].size(), 3u);
    EXPECT_EQ(j["bands"][0]["block"][0], 256);
    EXPECT_EQ(j["bands"][0]["block"][1], 256);
    ASSERT_EQ(j["bands"][0]["overviews"].size(), 1u);
    EXPECT_EQ(j["bands"][0]["overviews"][0]["size"][0], 250);
    EXPECT_NE(j["coordinateSystem"]["wkt"].get<std::string>().find("ID[\"EPSG\",4326]"), std::string::npos);
    // Corners: the DEM's own, to a millionth of a degree.
    const auto dem = nlohmann::json::parse(run("gdalinfo -json " + quote(kDem)).out);
    for (const char* corner : {"upperLeft", "lowerRight"})
        for (int k = 0; k < 2; ++k)
            EXPECT_NEAR(j["cornerCoordinates"][corner][k].get<double>(),
                        dem["cornerCoordinates"][corner][k].get<double>(), 1e-6) << corner;
    const Result valid = run("/usr/bin/python3 -m osgeo_utils.samples.validate_cloud_optimized_geotiff --full-check=yes " +
                             quote(tif.string()));
    EXPECT_EQ(valid.exit_code, 0) << valid.out << valid.err;
    EXPECT_NE(valid.out.find("is a valid cloud optimized GeoTIFF"), std::string::npos) << valid.out << valid.err;
    int tw = 0, th = 0, pw = 0, ph = 0;
    const auto a = read_rgb(tif, tw, th), b = read_rgb(png, pw, ph);
    ASSERT_EQ(tw, pw);
    ASSERT_EQ(th, ph);
    EXPECT_TRUE(a == b) << "the COG's pixels differ from the PNG's";
}

TEST(RenderCli, PerspectiveHasTheAskedSize) {
    const auto dir = temp_dir("render_persp");
    const auto out = dir / "view.png";
    const Result r = run(ts_cmd("render " + quote(kDem) + kCrop +
                                " --sun-azimuth 200 --sun-elevation 35 --view perspective --size 64x36 --out " +
                                quote(out.string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("camera:"), std::string::npos);
    EXPECT_EQ(png_size(out), std::make_pair(64, 36));
}

TEST(RenderCli, ExrIsWritten) {
    const auto dir = temp_dir("render_exr");
    const auto out = dir / "map.exr";
    const Result r = run(ts_cmd("render " + quote(kDem) + kCrop + " --sun-azimuth 180 --sun-elevation 40 --out " +
                                quote(out.string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(out));
    EXPECT_GT(std::filesystem::file_size(out), 1000u);
}

TEST(RenderCli, BadInputExitsTwoWithOneLine) {
    const auto dir = temp_dir("render_bad");
    const std::string out = " --out " + quote((dir / "x.png").string());
    const std::string dem = quote(kDem) + kCrop;
    for (const std::string& args : {
             "render " + dem + out,                                                  // no sun
             "render " + dem + " --time 2025-06-21T10:00:00Z --sun-azimuth 10 --sun-elevation 5" + out,
             "render " + dem + " --sun-azimuth 10" + out,                           // half a sun
             "render " + dem + " --time 2025-06-21T10:00:00" + out,                 // no zone
             "render " + dem + " --sun-azimuth 10 --sun-elevation 5 --out " + quote((dir / "x.jpg").string()),
             "render " + dem + " --sun-azimuth 10 --sun-elevation 5 --view perspective --camera 1,2,3" + out,
             "render " + dem + " --sun-azimuth 10 --sun-elevation 5 --camera 5.7,45.2,3000,0,-10,50" + out,
             "render " + dem + " --sun-azimuth 10 --sun-elevation 5 --size 10by10" + out,
             "render " + dem + " --sun-azimuth 10 --sun-elevation 5 --sky foggy" + out,
             "render " + dem + " --sun-azimuth 10 --sun-elevation 5 --exposure bright" + out,
             "render " + dem + " --sun-azimuth 10 --sun-elevation 5 --materials /nonexistent/cover.tif" + out,
             "render /nonexistent/dem.tif --sun-azimuth 10 --sun-elevation 5" + out,
         }) {
        const Result r = run(ts_cmd(args));
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

TEST(RelightCli, OneFramePerTimeAndSunDownWarns) {
    const auto dir = temp_dir("relight");
    // 02:00Z is before sunrise at Grenoble in June (night, -14 degrees): kept with --night
    // include, a sky-only frame and a warning.
    const Result r = run(ts_cmd("relight " + quote(kDem) + kCrop +
                                " --times 2025-06-21T02:00:00Z/2025-06-21T12:00:00Z/PT5H --night include --out " +
                                quote((dir / "frames").string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("below the horizon in 1 of 3 frames"), std::string::npos) << r.err;
    for (const char* name : {"frame_0000_2025-06-21T0200Z.png", "frame_0001_2025-06-21T0700Z.png",
                             "frame_0002_2025-06-21T1200Z.png"}) {
        const auto f = dir / "frames" / name;
        ASSERT_TRUE(std::filesystem::exists(f)) << f;
        EXPECT_EQ(png_size(f), std::make_pair(101, 101));
    }
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir / "frames"), {}), 4);  // + times.csv
}

TEST(RelightCli, SeveralWriterThreadsWriteEveryFrame) {
    const auto dir = temp_dir("relight_writers");
    const Result r = run(ts_cmd("relight " + quote(kDem) + kCrop +
                                " --times 2025-06-21T06:00:00Z/2025-06-21T16:00:00Z/PT2H --writer-threads 3 --out " +
                                quote((dir / "frames").string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir / "frames")) {
        if (e.path().filename() == "times.csv") continue;
        ++files;
        EXPECT_EQ(e.path().filename().string().rfind("frame_000", 0), 0u) << e.path();  // no temporary left
        EXPECT_EQ(png_size(e.path()), std::make_pair(101, 101)) << e.path();
    }
    EXPECT_EQ(files, 6);
    const Result bad = run(ts_cmd("relight " + quote(kDem) + kCrop + " --times 2025-06-21T06:00:00Z/2025-06-21T08:00:00Z/PT1H" +
                                  " --writer-threads 0 --out " + quote((dir / "bad").string())));
    EXPECT_EQ(bad.exit_code, 2) << bad.err;
}

TEST(RelightCli, TimesFileAndErrors) {
    const auto dir = temp_dir("relight_file");
    const auto times = dir / "times.txt";
    std::ofstream(times) << "# two instants\n2025-03-20T09:00:00Z\n\n2025-03-20T15:00:00+01:00\n";
    Result r = run(ts_cmd("relight " + quote(kDem) + kCrop + " --times-file " + quote(times.string()) + " --out " +
                          quote((dir / "a").string()) + " --format tif"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "a" / "frame_0001_2025-03-20T1400Z.tif"));
    std::ofstream(dir / "bad.txt") << "2025-03-20T09:00:00Z\nyesterday\n";
    for (const std::string& args : {
             "relight " + quote(kDem) + kCrop + " --times-file " + quote((dir / "bad.txt").string()),
             "relight " + quote(kDem) + kCrop + " --times 2025-03-20T09:00:00Z/2025-03-19T09:00:00Z/PT1H",
             "relight " + quote(kDem) + kCrop,
         }) {
        r = run(ts_cmd(args + " --out " + quote((dir / "b").string())));
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
    }
}

TEST(BenchRelightCli, PrintsTheRate) {
    const Result r = run(ts_cmd("bench relight " + quote(kDem) + kCrop + " --frames 2"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("relight: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" Mpx/s"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("end-to-end with files"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace ts::cli_test
