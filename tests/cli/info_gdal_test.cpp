// `terrashade info --json` against `gdalinfo -json -stats -hist` and `gdaltransform` (GDAL as
// an oracle only) for every shared DEM and for gdalwarp copies in each CRS family it supports.
#include <cmath>

#include <gtest/gtest.h>

#include "core/util/angles.hpp"
#include "tests/cli/cli_support.hpp"
#include "tests/support/shared_data.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace ts::cli_test;
using ts::radians;

namespace {

// The target: corners within 1 cm.
constexpr double kCornerToleranceM = 0.01;
// Metres per degree, generous upper bounds (WGS84 meridian and equator): turn a lon/lat
// difference into a distance that is never underestimated.
constexpr double kMetresPerDegreeLat = 111700.0;
constexpr double kMetresPerDegreeLonAtEquator = 111320.0;

struct Case {
    std::string name;
    std::string source;  // file under TS_SHARED_DATA/dem (several separated by spaces = mosaic)
    std::string warp;    // `tool` arguments; empty = use the file as it is
    std::string tool = "gdalwarp";
    std::string edit;    // gdal_edit.py arguments applied afterwards (e.g. a rotated transform)
};

std::ostream& operator<<(std::ostream& os, const Case& c) { return os << c.name; }

const fs::path& work_dir() {
    static const fs::path dir = temp_dir("info_gdal");
    return dir;
}

using ts::test::shared_dem;

// The input files for a case, made once in the work dir (gdalinfo -stats writes .aux.xml
// beside its input, so even unchanged files are copied).
std::vector<fs::path> prepare(const Case& c) {
    std::vector<fs::path> files;
    std::istringstream names(c.source);
    std::string name;
    while (names >> name) {
        if (c.warp.empty()) {
            // In a folder of its own: gdal's SRTM driver needs the file's own name (N00E010.hgt).
            fs::create_directories(work_dir() / c.name);
            const fs::path copy = work_dir() / c.name / name;
            fs::copy_file(shared_dem(name), copy, fs::copy_options::overwrite_existing);
            files.push_back(copy);
        } else {
            const fs::path out = work_dir() / (c.name + ".tif");
            fs::remove(out);
            const Result r = run(c.tool + " -q " + c.warp + " " + quote(shared_dem(name).string()) + " " + quote(out.string()));
            EXPECT_EQ(r.exit_code, 0) << r.err;
            if (!c.edit.empty()) {
                const Result e = run("gdal_edit.py " + c.edit + " " + quote(out.string()));
                EXPECT_EQ(e.exit_code, 0) << e.err;
            }
            files.push_back(out);
        }
    }
    return files;
}

// What gdal reports for `files`: one file as is, several through a VRT mosaic (gdalbuildvrt).
fs::path gdal_view(const Case& c, const std::vector<fs::path>& files) {
    if (files.size() == 1) return files.front();
    const fs::path vrt = work_dir() / (c.name + ".vrt");
    std::string cmd = "gdalbuildvrt -q -overwrite " + quote(vrt.string());
    for (const auto& f : files) cmd += " " + quote(f.string());
    EXPECT_EQ(run(cmd).exit_code, 0);
    return vrt;
}

double metres_between_lonlat(double lon1, double lat1, double lon2, double lat2) {
    const double lat = radians(std::min(std::abs(lat1), 90.0));
    const double dx = (lon1 - lon2) * kMetresPerDegreeLonAtEquator * std::cos(lat);
    const double dy = (lat1 - lat2) * kMetresPerDegreeLat;
    return std::hypot(dx, dy);
}

class InfoAgreesWithGdal : public ::testing::TestWithParam<Case> {};

TEST_P(InfoAgreesWithGdal, SizeCrsCornersStatisticsAndVoids) {
    const Case& c = GetParam();
    const std::vector<fs::path> files = prepare(c);
    ASSERT_FALSE(files.empty());
    const fs::path view = gdal_view(c, files);

    std::string args;
    for (const auto& f : files) args += " " + quote(f.string());
    const Result ours_run = run(quote(terrashade()) + " info --json" + args);
    ASSERT_EQ(ours_run.exit_code, 0) << ours_run.err;
    const json ours = json::parse(ours_run.out);
    const Result gdal_run = run("gdalinfo -json -stats -hist " + quote(view.string()));
    ASSERT_EQ(gdal_run.exit_code, 0) << gdal_run.err;
    const json gdal = json::parse(gdal_run.out);

    // Size and CRS.
    const int w = gdal["size"][0], h = gdal["size"][1];
    EXPECT_EQ(ours["width"], w);
    EXPECT_EQ(ours["height"], h);
    if (gdal["stac"].contains("proj:epsg") && !gdal["stac"]["proj:epsg"].is_null()) {
        EXPECT_EQ(ours["epsg"], gdal["stac"]["proj:epsg"]);
    }
    const bool geographic = ours["crs_is_geographic"];
    EXPECT_EQ(geographic, gdal["coordinateSystem"]["wkt"].get<std::string>().rfind("GEOGCRS", 0) == 0);
    if (gdal.contains("metadata") && gdal["metadata"].contains("") && gdal["metadata"][""].contains("AREA_OR_POINT")) {
        EXPECT_EQ(ours["pixel_is_area"], gdal["metadata"][""]["AREA_OR_POINT"] == "Area");
    }

    // Corners in the CRS, from gdal's full-precision geotransform.
    const json& gt = gdal["geoTransform"];
    const std::array<std::pair<const char*, std::array<double, 2>>, 4> corners{{
        {"upper_left", {0.0, 0.0}}, {"upper_right", {double(w), 0.0}},
        {"lower_right", {double(w), double(h)}}, {"lower_left", {0.0, double(h)}}}};
    std::string pixels;
    for (const auto& [key, px] : corners) {
        const double x = gt[0].get<double>() + px[0] * gt[1].get<double>() + px[1] * gt[2].get<double>();
        const double y = gt[3].get<double>() + px[0] * gt[4].get<double>() + px[1] * gt[5].get<double>();
        const double ox = ours["corners_crs"][key][0], oy = ours["corners_crs"][key][1];
        const double err_m = geographic ? metres_between_lonlat(ox, oy, x, y) : std::hypot(ox - x, oy - y);
        EXPECT_LT(err_m, kCornerToleranceM) << key << " CRS: ours " << ox << "," << oy << " gdal " << x << "," << y;
        pixels += std::to_string(px[0]) + " " + std::to_string(px[1]) + "\n";
    }
    // Corners in lon/lat: gdaltransform maps the same pixel corners to EPSG:4326 (15 digits).
    const Result t = run("gdaltransform -t_srs EPSG:4326 " + quote(view.string()), pixels);
    ASSERT_EQ(t.exit_code, 0) << t.err;
    std::istringstream lines(t.out);
    for (const auto& [key, px] : corners) {
        double lon = 0, lat = 0, z = 0;
        ASSERT_TRUE(lines >> lon >> lat >> z) << t.out;
        const double olon = ours["corners_lonlat"][key][0], olat = ours["corners_lonlat"][key][1];
        EXPECT_LT(metres_between_lonlat(olon, olat, lon, lat), kCornerToleranceM)
            << key << " lon/lat: ours " << olon << "," << olat << " gdal " << lon << "," << lat;
    }

    // Statistics: gdal prints them with 14 significant digits; min/max are exact.
    const json& band = gdal["bands"][0];
    const json& stats = band["metadata"][""];
    EXPECT_EQ(ours["height_min"].get<double>(), std::stod(stats["STATISTICS_MINIMUM"].get<std::string>()));
    EXPECT_EQ(ours["height_max"].get<double>(), std::stod(stats["STATISTICS_MAXIMUM"].get<std::string>()));
    const double gdal_mean = std::stod(stats["STATISTICS_MEAN"].get<std::string>());
    EXPECT_NEAR(ours["height_mean"].get<double>(), gdal_mean, 1e-13 * std::abs(gdal_mean) + 1e-12);
    // Void count: every valid cell falls in one bucket of gdal's full histogram.
    long long valid = 0;
    for (const auto& b : band["histogram"]["buckets"]) valid += b.get<long long>();
    EXPECT_EQ(ours["nodata_count"].get<long long>(), (long long)w * h - valid);

    // A metric cell size that is positive and finite.
    EXPECT_GT(ours["cell_size_m"][0].get<double>(), 0.0);
    EXPECT_GT(ours["cell_size_m"][1].get<double>(), 0.0);
}

// Small outputs (-ts / -tr) keep each warp well under a second.
const Case kCases[] = {
    // Every shared DEM as it is.
    {"srtm_hgt", "N00E010.hgt", ""},
    {"srtm_hgt_zip", "N00E011.hgt.zip", ""},
    {"srtm_mosaic", "N00E010.hgt N00E011.hgt.zip", ""},
    {"srtm3_tif", "srtm3_N39E040_1000px.tif", ""},
    {"grenoble_point", "copernicus_N45E005_grenoble_500px.tif", ""},
    {"etopo_global", "etopo1_global_1deg.tif", ""},
    {"nodata_3x3", "nodata_3x3.tif", ""},
    // Reprojected copies, one per supported CRS family.
    {"utm_north_32637", "srtm3_N39E040_1000px.tif", "-t_srs EPSG:32637 -ts 250 250"},
    {"utm_north_32633", "N00E010.hgt", "-t_srs EPSG:32633 -ts 200 200"},
    {"utm_south_32733", "N00E010.hgt", "-t_srs EPSG:32733 -ts 200 200 -ot Float32 -co TILED=YES -co BLOCKXSIZE=64 -co BLOCKYSIZE=64"},
    {"etrs89_utm_25831", "copernicus_N45E005_grenoble_500px.tif", "-t_srs EPSG:25831 -ts 200 200 -co COMPRESS=DEFLATE"},
    {"web_mercator_3857", "copernicus_N45E005_grenoble_500px.tif", "-t_srs EPSG:3857 -ts 200 200"},
    {"laea_3035", "copernicus_N45E005_grenoble_500px.tif", "-t_srs EPSG:3035 -ts 200 200 -co COMPRESS=LZW -co PREDICTOR=2"},
    {"lcc_2154", "copernicus_N45E005_grenoble_500px.tif", "-t_srs EPSG:2154 -ts 200 200"},
    {"polar_north_3413", "etopo1_global_1deg.tif", "-t_srs EPSG:3413 -te -3000000 -3000000 3000000 3000000 -tr 50000 50000 -dstnodata -32768"},
    {"polar_south_3031", "etopo1_global_1deg.tif", "-t_srs EPSG:3031 -te -3000000 -3000000 3000000 3000000 -tr 50000 50000"},
    {"albers_5070", "etopo1_global_1deg.tif", "-t_srs EPSG:5070 -te -2500000 0 2500000 3500000 -tr 25000 25000"},
    {"albers_3577", "etopo1_global_1deg.tif", "-t_srs EPSG:3577 -te -2000000 -5000000 2500000 -1000000 -tr 25000 25000 -ot Float64"},
    // GeoTIFF variants: PixelIsPoint in a projected CRS, and a rotated grid (ModelTransformation).
    {"utm_pixel_is_point", "srtm3_N39E040_1000px.tif",
     "-outsize 100 100 -a_srs EPSG:32637 -a_ullr 500000 4400000 503000 4397000 -mo AREA_OR_POINT=Point", "gdal_translate"},
    {"rotated_model_transformation", "srtm3_N39E040_1000px.tif",
     "-outsize 100 80 -a_srs EPSG:32633 -a_ullr 500000 5000000 503000 4997600", "gdal_translate",
     "-a_ulurll 500000 5000000 502900 5000700 500600 4997500"},
};

// A DEM added to the shared folder must get a case above, or this fails.
TEST(InfoAgreesWithGdalCoverage, EverySharedDemHasACase) {
    for (const auto& entry : fs::directory_iterator(fs::path(TS_SHARED_DATA) / "dem")) {
        const std::string name = entry.path().filename().string();
        bool covered = false;
        for (const Case& c : kCases) covered = covered || (c.warp.empty() && c.source.find(name) != std::string::npos);
        EXPECT_TRUE(covered) << name << " has no InfoAgreesWithGdal case";
    }
}

INSTANTIATE_TEST_SUITE_P(SharedDems, InfoAgreesWithGdal, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& p) { return p.param.name; });

}  // namespace
