#pragma once
// What the reliability tests (test_cli_reliability: io_plan, outputs, interrupt) share: the
// shipped DEM, a small crop and sun, the command line and a file's bytes.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/cli/cli_support.hpp"
#include "tests/cli/mbtiles_probe.hpp"

namespace ts::cli_test {

inline const std::string kDem = std::string(TS_SOURCE_DIR) + "/data/grenoble_500px.tif";
inline const std::string kCrop = " --crop 5.65,45.10,5.85,45.30";  // 101 x 101 texels
inline const std::string kSun = " --sun-azimuth 135 --sun-elevation 30";

inline std::string ts_cmd(const std::string& args) { return quote(terrashade()) + " " + args; }

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace ts::cli_test
