// Each bad input `info` must reject, through the real command: exit code 2, exactly one line on
// stderr naming the file, no crash. Also the happy paths a user types first.
#include <sys/resource.h>

#include <gtest/gtest.h>
#include <zip.h>

#include "tests/cli/cli_support.hpp"
#include "tests/dem/dem_test_files.hpp"
#include "tests/support/shared_data.hpp"

namespace fs = std::filesystem;
using namespace ts::cli_test;

namespace {

using ts::test::shared_dem;

std::string read_all(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void write_all(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

void expect_one_line_error(const fs::path& file, const std::string& problem) {
    const Result r = run(quote(terrashade()) + " info " + quote(file.string()));
    EXPECT_EQ(r.exit_code, 2) << file << ": " << r.err;
    ASSERT_FALSE(r.err.empty()) << file;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(file.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(problem), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
}

// A GeoTIFF whose ProjectedCSTypeGeoKey names no EPSG CRS: gdal writes 32633, we patch the
// key's value (GeoKeyDirectory entry 3072, location 0, count 1, value) to 29999.
void write_unknown_crs_tiff(const fs::path& out) {
    const fs::path good = out.parent_path() / "utm33.tif";
    ASSERT_EQ(run("gdal_create -q -of GTiff -outsize 4 4 -ot Int16 -a_srs EPSG:32633 -a_ullr 500000 5000000 500120 4999880 " +
                  quote(good.string())).exit_code, 0);
    std::string bytes = read_all(good);
    const std::string key{'\x00', '\x0c', '\x00', '\x00', '\x01', '\x00', '\x79', '\x7f'};  // 3072,0,1,32633 LE
    const auto at = bytes.find(key);
    ASSERT_NE(at, std::string::npos);
    bytes[at + 6] = char(29999 & 0xff);
    bytes[at + 7] = char(29999 >> 8);
    write_all(out, bytes);
}

// The largest resident set of any child this process has waited for, MB.
long children_peak_rss_mb() {
    rusage usage{};
    getrusage(RUSAGE_CHILDREN, &usage);
    return usage.ru_maxrss / 1024;
}

}  // namespace

// A 4x4 GeoTIFF (a few hundred bytes) whose header is edited to claim 40000x40000 cells, as
// a truncated download or a corrupt header would: refused from the file size in one line,
// the command never growing towards the 8 GB the header implies.
TEST(InfoBadInput, LyingHeaderIsRefusedBeforeItsRasterIsAllocated) {
    const fs::path dir = temp_dir("info_lying");
    const fs::path small = dir / "small.tif";
    ASSERT_EQ(run("gdal_create -q -of GTiff -outsize 4 4 -ot Int16 -a_srs EPSG:4326 -a_ullr 10 1 11 0 " +
                  quote(small.string())).exit_code, 0);
    std::string bytes = read_all(small);
    ASSERT_TRUE(ts::dem::test_files::patch_tiff_tag(bytes, 256, 40000));  // ImageWidth
    ASSERT_TRUE(ts::dem::test_files::patch_tiff_tag(bytes, 257, 40000));  // ImageLength
    ASSERT_TRUE(ts::dem::test_files::patch_tiff_tag(bytes, 278, 40000));  // RowsPerStrip: one strip of all rows
    write_all(dir / "lying.tif", bytes);
    ASSERT_LT(bytes.size(), 1000u);
    expect_one_line_error(dir / "lying.tif", "truncated");
    EXPECT_LT(children_peak_rss_mb(), 500);
}

// +Inf and -Inf heights in a float32 GeoTIFF are voids, like NaN: counted as voids, not in
// the height statistics.
TEST(Info, InfiniteHeightsAreVoids) {
    const fs::path dir = temp_dir("info_inf");
    const fs::path plain = dir / "plain.tif";
    ASSERT_EQ(run("gdal_create -q -of GTiff -outsize 4 3 -ot Float32 -burn 1234.5 -a_srs EPSG:4326 -a_ullr 10 1 11 0 " +
                  quote(plain.string())).exit_code, 0);
    std::string bytes = read_all(plain);
    const std::string value{'\x00', '\x50', '\x9a', '\x44'};  // 1234.5f, little-endian
    const auto first = bytes.find(value);
    ASSERT_NE(first, std::string::npos);
    ASSERT_EQ(bytes.compare(first + 11 * 4, 4, value), 0);  // the 12 samples, one after another
    bytes.replace(first, 4, std::string{'\x00', '\x00', '\x80', '\x7f'});           // +Inf
    bytes.replace(first + 11 * 4, 4, std::string{'\x00', '\x00', '\x80', '\xff'});  // -Inf
    write_all(dir / "inf.tif", bytes);

    const Result r = run(quote(terrashade()) + " info --json " + quote((dir / "inf.tif").string()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["nodata_count"], 2);
    EXPECT_EQ(j["height_min"], 1234.5);
    EXPECT_EQ(j["height_max"], 1234.5);

    const Result all = run("gdal_create -q -of GTiff -outsize 4 3 -ot Float32 -burn -inf -a_srs EPSG:4326 -a_ullr 10 1 11 0 " +
                           quote((dir / "minus_inf.tif").string()));
    ASSERT_EQ(all.exit_code, 0);
    const Result text = run(quote(terrashade()) + " info " + quote((dir / "minus_inf.tif").string()));
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("none (every cell is a void)"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("voids        12 of 12"), std::string::npos) << text.out;
}

TEST(InfoBadInput, EachCaseExitsTwoWithOneLineNamingTheFile) {
    const fs::path dir = temp_dir("info_bad");
    const std::string tile = read_all(shared_dem("N00E010.hgt"));

    write_all(dir / "N10E010.hgt", "");
    expect_one_line_error(dir / "N10E010.hgt", "empty file");

    write_all(dir / "N11E010.hgt", tile.substr(0, 1000000));
    expect_one_line_error(dir / "N11E010.hgt", "truncated");

    write_all(dir / "N12E010.hgt", tile + "\x01");
    expect_one_line_error(dir / "N12E010.hgt", "not an SRTM .hgt tile");

    {
        int err = 0;
        zip_t* z = zip_open((dir / "N13E010.hgt.zip").string().c_str(), ZIP_CREATE | ZIP_TRUNCATE, &err);
        const std::string text = "not a tile";
        zip_file_add(z, "readme.txt", zip_source_buffer(z, text.data(), text.size(), 0), ZIP_FL_OVERWRITE);
        zip_close(z);
    }
    expect_one_line_error(dir / "N13E010.hgt.zip", "no .hgt");

    ASSERT_EQ(run("gdal_create -q -of GTiff -outsize 16 8 -bands 3 -ot Byte -burn 200 " + quote((dir / "photo.tif").string())).exit_code, 0);
    expect_one_line_error(dir / "photo.tif", "samples per pixel");

    ASSERT_EQ(run("gdal_create -q -of GTiff -outsize 16 8 -ot Int16 " + quote((dir / "plain.tif").string())).exit_code, 0);
    expect_one_line_error(dir / "plain.tif", "without georeferencing");

    write_unknown_crs_tiff(dir / "unknown_crs.tif");
    expect_one_line_error(dir / "unknown_crs.tif", "unknown coordinate reference system");

    fs::create_directories(dir / "a_folder");
    expect_one_line_error(dir / "a_folder", "is a directory");

    expect_one_line_error(dir / "N14E010.hgt", "no such file");
}

TEST(InfoBadInput, MismatchedMosaicAndBadCropAreInputErrors) {
    const Result mixed = run(quote(terrashade()) + " info " + quote(shared_dem("N00E010.hgt").string()) + " " +
                             quote(shared_dem("srtm3_N39E040_1000px.tif").string()));
    EXPECT_EQ(mixed.exit_code, 2);
    EXPECT_EQ(std::count(mixed.err.begin(), mixed.err.end(), '\n'), 1) << mixed.err;
    EXPECT_NE(mixed.err.find("srtm3_N39E040_1000px.tif"), std::string::npos) << mixed.err;

    const Result crop = run(quote(terrashade()) + " info --crop 50,0,51,1 " + quote(shared_dem("N00E010.hgt").string()));
    EXPECT_EQ(crop.exit_code, 2);
    EXPECT_NE(crop.err.find("does not overlap"), std::string::npos) << crop.err;

    const Result none = run(quote(terrashade()) + " info");
    EXPECT_EQ(none.exit_code, 2);
}

TEST(Info, TextAndJsonForATileAndACrop) {
    const Result text = run(quote(terrashade()) + " info " + quote(shared_dem("N00E010.hgt").string()));
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("EPSG:4326"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("pixel is point"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("EGM96"), std::string::npos) << text.out;

    const Result crop = run(quote(terrashade()) + " info --json --crop 10.25,0.5,10.5,0.75 " +
                            quote(shared_dem("N00E010.hgt").string()));
    ASSERT_EQ(crop.exit_code, 0) << crop.err;
    const auto j = nlohmann::json::parse(crop.out);
    EXPECT_EQ(j["width"], 301);  // cell edges at (k - 0.5)/1200 deg: 301 cells overlap a 0.25 deg box
    EXPECT_EQ(j["height"], 301);

    const Result help = run(quote(terrashade()) + " info --help");
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.out.find("mosaic"), std::string::npos) << help.out;
}

// Heights stored in feet (a vertical CRS in US survey feet, or GDAL's band unit type) are read
// as metres: the relief is not exaggerated 3.28 times. A unit that is no length is refused.
TEST(Info, HeightsInFeetAreConvertedToMetres) {
    const fs::path dir = temp_dir("info_feet");
    const std::string metres = (dir / "m.tif").string(), feet = (dir / "ft.tif").string();
    const std::string vertical = (dir / "ftv.tif").string(), typed = (dir / "ftt.tif").string();
    ASSERT_EQ(run("gdal_translate -q -ot Float32 -srcwin 0 0 64 64 " + quote(kDem) + " " + quote(metres)).exit_code, 0);
    ASSERT_EQ(run("gdal_calc.py --quiet -A " + quote(metres) + " --outfile=" + quote(feet) +
                  " --type=Float32 --calc=A/0.3048006096012192")
                  .exit_code,
              0);
    // The vertical CRS NAVD88 height (ftUS), as a compound CRS's GeoKeys.
    ASSERT_EQ(run("gdal_translate -q -a_srs EPSG:4326+6360 " + quote(feet) + " " + quote(vertical)).exit_code, 0);
    // GDAL's band unit type alone.
    ASSERT_EQ(run("gdal_translate -q " + quote(feet) + " " + quote(typed) + " && gdal_edit.py -units 'US survey foot' " +
                  quote(typed))
                  .exit_code,
              0);
    auto stats = [](const std::string& file) {
        const Result r = run(quote(terrashade()) + " info --json " + quote(file));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json{};
    };
    const auto m = stats(metres);
    EXPECT_EQ(m["height_unit"], "metre");
    for (const std::string& f : {vertical, typed}) {
        const auto j = stats(f);
        EXPECT_EQ(j["height_unit"], "US survey foot") << f;
        EXPECT_NEAR(j["height_max"].get<double>(), m["height_max"].get<double>(), 1e-3) << f;
        EXPECT_NEAR(j["height_mean"].get<double>(), m["height_mean"].get<double>(), 1e-3) << f;
    }
    const std::string odd = (dir / "odd.tif").string();
    ASSERT_EQ(run("gdal_translate -q " + quote(metres) + " " + quote(odd) + " && gdal_edit.py -units furlong " + quote(odd))
                  .exit_code,
              0);
    const Result r = run(quote(terrashade()) + " info " + quote(odd));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("furlong"), std::string::npos) << r.err;
}

// A user-defined CRS with a datum shift (+towgs84, GeogTOWGS84GeoKey) is placed as GDAL places
// it, and a GeoTIFF written from it keeps the shift: libgeotiff's PROJ strings leave it out,
// which put ED50 in France 140 m off.
TEST(Info, ADatumShiftInUserDefinedKeysIsKept) {
    const fs::path dir = temp_dir("info_towgs84");
    const std::string ed50 = (dir / "ed50.tif").string(), shade = (dir / "shade.tif").string();
    const std::string srs = "+proj=tmerc +lat_0=45 +lon_0=5.5 +k=1 +x_0=0 +y_0=0 +ellps=intl "
                            "+towgs84=-87,-98,-121,0,0,0,0 +units=m";
    ASSERT_EQ(run("gdalwarp -q -t_srs '" + srs + "' -ts 60 60 " + quote(kDem) + " " + quote(ed50)).exit_code, 0);
    const auto upper_left = [](const std::string& file) {
        const Result r = run(quote(terrashade()) + " info --json " + quote(file));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return r.exit_code == 0 ? nlohmann::json::parse(r.out)["corners_lonlat"]["upper_left"] : nlohmann::json{};
    };
    const Result gdal = run("gdalinfo -json " + quote(ed50));
    ASSERT_EQ(gdal.exit_code, 0);
    const auto g = nlohmann::json::parse(gdal.out)["cornerCoordinates"]["upperLeft"];
    const Result t = run("echo " + std::to_string(g[0].get<double>()) + " " + std::to_string(g[1].get<double>()) +
                         " | gdaltransform -output_xy -s_srs '" + srs + "' -t_srs EPSG:4326");
    double lon = 0, lat = 0;
    ASSERT_EQ(std::sscanf(t.out.c_str(), "%lf %lf", &lon, &lat), 2) << t.out;
    const auto mine = upper_left(ed50);
    EXPECT_NEAR(mine[0].get<double>(), lon, 1e-6);  // 1e-6 degree: 0.1 m; the shift is ~1e-3
    EXPECT_NEAR(mine[1].get<double>(), lat, 1e-6);
    ASSERT_EQ(run(quote(terrashade()) + " hillshade " + quote(ed50) + " -o " + quote(shade)).exit_code, 0);
    const auto written = upper_left(shade);
    EXPECT_NEAR(written[0].get<double>(), lon, 1e-6);
    EXPECT_NEAR(written[1].get<double>(), lat, 1e-6);
}
