// Each bad input `info` must reject, through the real command: exit code 2, exactly one line on
// stderr naming the file, no crash. Also the happy paths a user types first.
#include <gtest/gtest.h>
#include <zip.h>

#include "tests/cli/cli_support.hpp"

namespace fs = std::filesystem;
using namespace ts::cli_test;

namespace {

fs::path shared(const std::string& name) { return fs::path(TS_SHARED_DATA) / "dem" / name; }

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

}  // namespace

TEST(InfoBadInput, EachCaseExitsTwoWithOneLineNamingTheFile) {
    const fs::path dir = temp_dir("info_bad");
    const std::string tile = read_all(shared("N00E010.hgt"));

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
    const Result mixed = run(quote(terrashade()) + " info " + quote(shared("N00E010.hgt").string()) + " " +
                             quote(shared("srtm3_N39E040_1000px.tif").string()));
    EXPECT_EQ(mixed.exit_code, 2);
    EXPECT_EQ(std::count(mixed.err.begin(), mixed.err.end(), '\n'), 1) << mixed.err;
    EXPECT_NE(mixed.err.find("srtm3_N39E040_1000px.tif"), std::string::npos) << mixed.err;

    const Result crop = run(quote(terrashade()) + " info --crop 50,0,51,1 " + quote(shared("N00E010.hgt").string()));
    EXPECT_EQ(crop.exit_code, 2);
    EXPECT_NE(crop.err.find("does not overlap"), std::string::npos) << crop.err;

    const Result none = run(quote(terrashade()) + " info");
    EXPECT_EQ(none.exit_code, 2);
}

TEST(Info, TextAndJsonForATileAndACrop) {
    const Result text = run(quote(terrashade()) + " info " + quote(shared("N00E010.hgt").string()));
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("EPSG:4326"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("pixel is point"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("EGM96"), std::string::npos) << text.out;

    const Result crop = run(quote(terrashade()) + " info --json --crop 10.25,0.5,10.5,0.75 " +
                            quote(shared("N00E010.hgt").string()));
    ASSERT_EQ(crop.exit_code, 0) << crop.err;
    const auto j = nlohmann::json::parse(crop.out);
    EXPECT_EQ(j["width"], 301);  // cell edges at (k - 0.5)/1200 deg: 301 cells overlap a 0.25 deg box
    EXPECT_EQ(j["height"], 301);

    const Result help = run(quote(terrashade()) + " info --help");
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.out.find("mosaic"), std::string::npos) << help.out;
}
