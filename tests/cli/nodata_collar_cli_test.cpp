// A DEM reprojected by gdalwarp (GDAL as a tool only) has a nodata collar around its terrain:
// `info` counts it as outside, and `hillshade`, `render` and `tiles` leave it transparent (an
// alpha channel), with the MBTiles bounds those of the terrain, not of the collared grid.
#include <sqlite3.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.hpp"
#include "tests/cli/frame_pixels.hpp"

namespace fs = std::filesystem;
using ts::cli_test::Pixels;
using ts::cli_test::quote;
using ts::cli_test::read_pixels;
using ts::cli_test::Result;
using ts::cli_test::run;
using ts::cli_test::temp_dir;
using ts::cli_test::terrashade;

namespace {

Pixels read_image(const fs::path& path) {
    Pixels p = read_pixels(path);
    EXPECT_GT(p.width, 0) << path;
    return p;
}

// The Grenoble DEM (lon/lat, 5-6 E, 45-46 N) in ETRS89-LAEA at 1 km cells: a ~80 x 113 grid
// whose corners are nodata (the lon/lat square is a tilted quadrilateral in EPSG:3035).
const fs::path& reprojected() {
    static const fs::path file = [] {
        const fs::path out = temp_dir("nodata_collar") / "grenoble_3035.tif";
        fs::remove(out);
        const Result r = run("gdalwarp -q -t_srs EPSG:3035 -tr 1000 1000 " +
                             quote(ts::cli_test::kDem) + " " + quote(out.string()));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return out;
    }();
    return file;
}

std::string ts(const std::string& args) { return quote(terrashade()) + " " + args; }

TEST(NodataCollarCli, InfoCountsTheCollarAsOutside) {
    const Result r = run(ts("info --json " + quote(reprojected().string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const long long total = j["width"].get<long long>() * j["height"].get<long long>();
    EXPECT_GT(j["nodata_outside_count"].get<long long>(), total / 10);
    EXPECT_EQ(j["nodata_outside_count"].get<long long>(), j["nodata_count"].get<long long>());
    EXPECT_EQ(j["nodata_hole_count"].get<long long>(), 0);
}

TEST(NodataCollarCli, HillshadeIsGreyAndAlphaTransparentOverTheCollar) {
    const fs::path out = temp_dir("nodata_collar_hs") / "hs.png";
    const Result r = run(ts("hillshade " + quote(reprojected().string()) + " --out " + quote(out.string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Pixels p = read_image(out);
    ASSERT_EQ(p.channels, 2);
    EXPECT_EQ(p.at(0, 0, 1), 0);                               // a corner: collar
    EXPECT_EQ(p.at(p.width / 2, p.height / 2, 1), 255);        // the middle: terrain
    EXPECT_GT(p.at(p.width / 2, p.height / 2, 0), 0);
}

TEST(NodataCollarCli, RenderIsTransparentOverTheCollarOnly) {
    const fs::path out = temp_dir("nodata_collar_render") / "map.png";
    const Result r = run(ts("render " + quote(reprojected().string()) +
                            " --directions 8 --sun-azimuth 135 --sun-elevation 30 --out " + quote(out.string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Pixels p = read_image(out);
    ASSERT_EQ(p.channels, 4);
    EXPECT_EQ(p.at(0, 0, 3), 0);
    EXPECT_EQ(p.at(p.width - 1, p.height - 1, 3), 0);
    std::size_t transparent = 0;
    for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) transparent += p.at(x, y, 3) == 0;
    // The collar is a share of the picture, the terrain the rest (opaque, and not one flat grey).
    EXPECT_GT(transparent, std::size_t(p.width * p.height) / 10);
    EXPECT_LT(transparent, std::size_t(p.width * p.height) / 2);
    EXPECT_EQ(p.at(p.width / 2, p.height / 2, 3), 255);
}

TEST(NodataCollarCli, TilesAreTransparentOverTheCollarAndTheBoundsAreTheTerrains) {
    const fs::path out = temp_dir("nodata_collar_tiles") / "t.mbtiles";
    const Result r = run(ts("tiles " + quote(reprojected().string()) + " --zoom 7-8 --style hillshade --out " +
                            quote(out.string())));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open_v2(out.c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
    std::map<std::string, std::string> meta;
    sqlite3_stmt* q = nullptr;
    sqlite3_prepare_v2(db, "SELECT name, value FROM metadata", -1, &q, nullptr);
    while (sqlite3_step(q) == SQLITE_ROW)
        meta[reinterpret_cast<const char*>(sqlite3_column_text(q, 0))] = reinterpret_cast<const char*>(sqlite3_column_text(q, 1));
    sqlite3_finalize(q);
    // The terrain is the lon/lat square 5-6 E, 45-46 N (to a 1 km cell); the collared grid's
    // outline reaches further (its corners are off that square by several km).
    double w = 0, s = 0, e = 0, n = 0;
    ASSERT_EQ(std::sscanf(meta["bounds"].c_str(), "%lf,%lf,%lf,%lf", &w, &s, &e, &n), 4) << meta["bounds"];
    EXPECT_NEAR(w, 5.0, 0.02);
    EXPECT_NEAR(e, 6.0, 0.02);
    EXPECT_NEAR(s, 45.0, 0.02);
    EXPECT_NEAR(n, 46.0, 0.02);
    // Every pixel clearly outside the lon/lat square (over the collar or off the grid) is
    // transparent, every pixel clearly inside it opaque; and the collar is seen by some tile.
    const fs::path tile = out.parent_path() / "tile.png";
    std::size_t outside = 0, inside = 0, tiles = 0;
    sqlite3_prepare_v2(db, "SELECT zoom_level, tile_column, tile_row, tile_data FROM tiles", -1, &q, nullptr);
    while (sqlite3_step(q) == SQLITE_ROW) {
        const int z = sqlite3_column_int(q, 0), x = sqlite3_column_int(q, 1);
        const int y = (1 << z) - 1 - sqlite3_column_int(q, 2);  // TMS rows
        {
            FILE* f = std::fopen(tile.c_str(), "wb");
            ASSERT_TRUE(f);
            std::fwrite(sqlite3_column_blob(q, 3), 1, std::size_t(sqlite3_column_bytes(q, 3)), f);
            std::fclose(f);
        }
        const Pixels p = read_image(tile);
        ASSERT_TRUE(p.channels == 2 || p.channels == 4);
        ++tiles;
        const double world = double(p.width) * double(1 << z);
        for (int j = 0; j < p.height; ++j)
            for (int i = 0; i < p.width; ++i) {
                const double lon = (x * double(p.width) + i + 0.5) / world * 360.0 - 180.0;
                const double lat =
                    std::atan(std::sinh(M_PI * (1.0 - 2.0 * (y * double(p.height) + j + 0.5) / world))) * 180.0 / M_PI;
                const unsigned char alpha = p.at(i, j, p.channels - 1);
                const double margin = 0.02;  // a 1 km cell and a zoom-8 pixel
                if (lon < 5.0 - margin || lon > 6.0 + margin || lat < 45.0 - margin || lat > 46.0 + margin) {
                    ASSERT_EQ(alpha, 0) << z << "/" << x << "/" << y << " " << i << "," << j;
                    ++outside;
                } else if (lon > 5.0 + margin && lon < 6.0 - margin && lat > 45.0 + margin && lat < 46.0 - margin) {
                    ASSERT_EQ(alpha, 255) << z << "/" << x << "/" << y << " " << i << "," << j;
                    ++inside;
                }
            }
    }
    EXPECT_GT(tiles, 0u);
    EXPECT_GT(outside, 0u);
    EXPECT_GT(inside, 0u);
    sqlite3_finalize(q);
    sqlite3_close(db);
}

}  // namespace

namespace {

// A hole inside the terrain is filled (its neighbours are shaded with the invented heights) but
// not shown: render's map and extent leave it transparent, as hillshade does, where it was drawn
// as dark water.
TEST(NodataCollarCli, AFilledHoleIsTransparentInEveryMap) {
    const fs::path dir = temp_dir("filled_hole");
    const fs::path dem = dir / "hole.tif";
    ASSERT_EQ(run("gdal_translate -q -ot Float32 -a_nodata -9999 -srcwin 100 100 60 60 " + quote(ts::cli_test::kDem) +
                  " " + quote(dem.string()) + " && /usr/bin/python3 -c \"from osgeo import gdal; d = gdal.Open('" +
                  dem.string() + "', 1); a = d.ReadAsArray(); a[25:35, 25:35] = -9999; d.GetRasterBand(1).WriteArray(a)\"")
                  .exit_code,
              0);
    const std::string hole = quote(dem.string());
    for (const std::string& args : {std::string(""), std::string(" --extent 5.23,45.72,5.28,45.76 --extent-crs EPSG:4326 --size 60x60")}) {
        const fs::path out = dir / "map.png";
        const Result r = run(ts("render " + hole + " --directions 8 --sun-azimuth 135 --sun-elevation 30" + args +
                                " --out " + quote(out.string())));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const Pixels p = read_image(out);
        ASSERT_EQ(p.channels, 4) << args;
        if (args.empty()) {
            EXPECT_EQ(p.at(30, 30, 3), 0) << "the hole's middle";
            EXPECT_EQ(p.at(10, 10, 3), 255) << "measured terrain";
        }
        std::size_t transparent = 0;
        for (int y = 0; y < p.height; ++y)
            for (int x = 0; x < p.width; ++x) transparent += p.at(x, y, 3) == 0;
        EXPECT_GT(transparent, 0u) << args;
    }
}

}  // namespace
