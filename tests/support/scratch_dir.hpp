#pragma once
// Scratch folders and file reads the tests share (one definition, so that a unity batch of
// several test files compiles).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

#include <unistd.h>

namespace ts::test {

// A fresh, empty folder under a per-process temp folder that is removed when the process ends.
inline std::filesystem::path fresh_dir(const std::string& name) {
    struct Root {
        std::filesystem::path path = std::filesystem::temp_directory_path() / ("ts_test_" + std::to_string(::getpid()));
        ~Root() {
            std::error_code ec;
            std::filesystem::remove_all(path, ec);
        }
    };
    static const Root root;
    const auto d = root.path / name;
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

// A whole file as bytes ("" when it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace ts::test
