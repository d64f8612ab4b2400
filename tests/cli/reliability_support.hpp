#pragma once
// What the reliability tests (io_plan, outputs, interrupt) share besides cli_support.hpp: a
// file's bytes and a times.csv's files.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tests/cli/cli_support.hpp"
#include "tests/cli/mbtiles_probe.hpp"

namespace ts::cli_test {

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
