// Every bad input is one ts::InputError whose message starts with the file's path.
#include <fstream>

#include <gtest/gtest.h>
#include <zip.h>

#include "core/dem/read_dem.hpp"
#include "core/util/error.hpp"
#include "tests/dem/dem_test_files.hpp"

using namespace ts::dem;
namespace fs = std::filesystem;

namespace {

// The message read_dem throws for `path`; fails the test if it throws nothing or something else.
std::string error_for(const fs::path& path) {
    try {
        read_dem(path);
    } catch (const ts::InputError& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << path << ": threw a non-InputError: " << e.what();
        return {};
    }
    ADD_FAILURE() << path << ": read without error";
    return {};
}

void expect_error(const fs::path& path, const std::string& problem) {
    const std::string msg = error_for(path);
    EXPECT_EQ(msg.rfind(path.string() + ": ", 0), 0u) << msg;  // starts with "path: "
    EXPECT_NE(msg.find(problem), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;  // one line
}

}  // namespace

TEST(BadInput, EachCaseIsOneLineNamingTheFile) {
    const fs::path dir = test_files::fresh_dir("bad");
    const std::string tile = test_files::synthetic_hgt();

    test_files::write_bytes(dir / "N00E010.hgt", "");
    expect_error(dir / "N00E010.hgt", "empty file");

    test_files::write_bytes(dir / "N01E010.hgt", tile.substr(0, tile.size() / 2));
    expect_error(dir / "N01E010.hgt", "truncated");

    test_files::write_bytes(dir / "N02E010.hgt", tile + "x");  // odd size
    expect_error(dir / "N02E010.hgt", "not an SRTM .hgt tile");

    test_files::write_bytes(dir / "tile.hgt", tile);  // no corner in the name
    expect_error(dir / "tile.hgt", "south-west corner");

    test_files::write_zip(dir / "N03E010.hgt.zip", "readme.txt", "no tile here");
    expect_error(dir / "N03E010.hgt.zip", "no .hgt");

    test_files::TiffSpec rgb;
    rgb.spp = 3;
    rgb.bits = 8;
    rgb.sample_format = 1;
    test_files::write_tiff(dir / "photo.tif", rgb, std::vector<std::uint8_t>(4 * 3 * 3, 128));
    expect_error(dir / "photo.tif", "3 samples per pixel");

    test_files::TiffSpec plain;
    plain.epsg = -1;
    test_files::write_tiff(dir / "plain.tif", plain, test_files::as_bytes(std::vector<std::int16_t>(12, 1)));
    expect_error(dir / "plain.tif", "without georeferencing");

    test_files::TiffSpec unknown;
    unknown.epsg = 29999;  // not an EPSG code
    unknown.geographic = false;
    test_files::write_tiff(dir / "unknown_crs.tif", unknown, test_files::as_bytes(std::vector<std::int16_t>(12, 1)));
    expect_error(dir / "unknown_crs.tif", "unknown coordinate reference system");

    test_files::TiffSpec keyless;  // a model type but no code and no user-defined parameters
    keyless.epsg = 0;
    keyless.geographic = false;
    test_files::write_tiff(dir / "keyless.tif", keyless, test_files::as_bytes(std::vector<std::int16_t>(12, 1)));
    expect_error(dir / "keyless.tif", "coordinate reference system");

    test_files::TiffSpec flat;  // a pixel scale of 0: every cell on one point
    flat.cell = 0;
    test_files::write_tiff(dir / "zero_scale.tif", flat, test_files::as_bytes(std::vector<std::int16_t>(12, 1)));
    expect_error(dir / "zero_scale.tif", "degenerate GeoTIFF georeferencing");

    test_files::write_bytes(dir / "truncated.tif", [&] {
        std::ifstream in(fs::path(TS_SHARED_DATA) / "dem" / "srtm3_N39E040_1000px.tif", std::ios::binary);
        std::string head(50000, '\0');
        in.read(head.data(), std::streamsize(head.size()));
        return head;
    }());
    expect_error(dir / "truncated.tif", "");

    test_files::write_bytes(dir / "notes.txt", "hello");
    expect_error(dir / "notes.txt", "unrecognised DEM format");

    fs::create_directories(dir / "folder.tif");
    expect_error(dir / "folder.tif", "is a directory");

    expect_error(dir / "missing.hgt", "no such file");
}
