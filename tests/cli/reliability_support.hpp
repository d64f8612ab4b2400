#pragma once
// What the reliability tests (test_cli_reliability: io_plan, outputs, interrupt) share: the
// shipped DEM, a small crop and sun, the command line, a file's bytes and a times.csv's files.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

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

// The `file` column of a relight folder's times.csv, in order.
inline std::vector<std::string> csv_files(const std::filesystem::path& times_csv) {
    std::ifstream in(times_csv);
    std::string line;
    std::getline(in, line);  // header
    std::vector<std::string> files;
    while (std::getline(in, line)) {
        const auto a = line.find(','), b = line.find(',', a + 1);
        files.push_back(line.substr(a + 1, b - a - 1));
    }
    return files;
}

}  // namespace ts::cli_test
