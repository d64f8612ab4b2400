#pragma once
// Helpers for the CLI tests: run a command, keep its exit code, stdout and
// stderr; a private temp dir per test binary; gdalinfo/gdaltransform as oracles (never linked).
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ts::cli_test {

struct Result {
    int exit_code = -1;
    std::string out, err;
};

inline std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

// A folder per test process, removed when the process ends.
inline const std::filesystem::path& temp_root() {
    struct Root {
        std::filesystem::path path =
            std::filesystem::temp_directory_path() / ("ts_cli_" + std::to_string(::getpid()));
        ~Root() {
            std::error_code ec;
            std::filesystem::remove_all(path, ec);
        }
    };
    static const Root root;
    return root.path;
}

inline std::filesystem::path temp_dir(const std::string& name) {
    auto d = temp_root() / name;
    std::filesystem::create_directories(d);
    return d;
}

// Runs `command` through the shell with `input` on stdin (if any).
inline Result run(const std::string& command, const std::string& input = "") {
    static int counter = 0;
    const auto dir = temp_dir("run");
    const auto err_path = dir / ("stderr" + std::to_string(counter++));
    std::string full = command;
    if (!input.empty()) {
        const auto in_path = dir / ("stdin" + std::to_string(counter++));
        std::ofstream(in_path) << input;
        full += " < " + quote(in_path.string());
    }
    full += " 2> " + quote(err_path.string());
    Result r;
    FILE* pipe = popen(full.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 65536> buf{};
    std::size_t n = 0;
    while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
    const int status = pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream e(err_path);
    std::stringstream ss;
    ss << e.rdbuf();
    r.err = ss.str();
    return r;
}

// The terrashade binary: TERRASHADE_BIN from the environment (to test an installed copy), else the build's.
inline std::string terrashade() {
    if (const char* env = std::getenv("TERRASHADE_BIN"); env && *env) return env;
    return TS_BIN;
}

// What most command tests run on: the shipped sample DEM, a 0.2 x 0.2 degree crop of it (101 x
// 101 texels, --crop keeps both edge texels: the city, the Isere and two massifs) and a sun.
inline const std::string kDem = std::string(TS_SOURCE_DIR) + "/data/grenoble_500px.tif";
inline const std::string kCrop = " --crop 5.65,45.10,5.85,45.30";
inline const std::string kSun = " --sun-azimuth 135 --sun-elevation 30";
// The shared DEMs' folder (../shared/data/dem/), with its trailing slash.
inline const std::string kSharedDems = std::string(TS_SHARED_DATA) + "/dem/";
// The driver manifests pointed at nothing: the Vulkan loader finds no device.
inline const std::string kNoVulkan = "VK_DRIVER_FILES=/nonexistent.json VK_ICD_FILENAMES=/nonexistent.json ";

// `terrashade ARGS` as a shell command.
inline std::string ts_cmd(const std::string& args) { return quote(terrashade()) + " " + args; }
// Runs `terrashade ARGS` after `env` (variable assignments such as kNoVulkan, or nothing).
inline Result run_ts(const std::string& args, const std::string& env = "") { return run(env + ts_cmd(args)); }

}  // namespace ts::cli_test
