#include "tests/fuzz/dem_fuzz_inputs.hpp"

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "core/dem/read_dem.hpp"
#include "core/util/error.hpp"

namespace ts::fuzz {

namespace {

namespace fs = std::filesystem;

// One scratch folder per process (libFuzzer's -jobs/-fork run several), removed at exit. In
// memory (/dev/shm) where there is one: rewriting a file on disk for every input costs
// ~3 ms, more than most reads.
fs::path scratch_root() {
    std::error_code ec;
    if (fs::is_directory("/dev/shm", ec) && ::access("/dev/shm", W_OK) == 0) return "/dev/shm";
    return fs::temp_directory_path();
}

const fs::path& scratch_dir() {
    struct Dir {
        fs::path path = scratch_root() / ("ts_fuzz_" + std::to_string(::getpid()));
        Dir() { fs::create_directories(path); }
        ~Dir() {
            std::error_code ec;
            fs::remove_all(path, ec);
        }
    };
    static const Dir dir;
    return dir.path;
}

fs::path write_input(const std::string& name, const std::uint8_t* data, std::size_t size) {
    const fs::path path = scratch_dir() / name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    if (!out) throw std::runtime_error("cannot write the fuzz input " + path.string());
    return path;
}

template <class Read>
Outcome outcome_of(Read read) {
    try {
        read();
        return Outcome::read;
    } catch (const InputError&) {
        return Outcome::input_error;
    }
}

}  // namespace

Outcome feed_hgt(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return outcome_of([] { dem::read_hgt_bytes("", "N00E010.hgt", "input.hgt"); });
    const std::uint8_t flags = data[0];
    const char* text = reinterpret_cast<const char*>(data + 1);
    const std::size_t rest = size - 1;
    const char* newline = static_cast<const char*>(std::memchr(text, '\n', rest));
    const std::size_t name_length = newline ? std::size_t(newline - text) : 0;
    const std::string name(text, name_length);
    std::string bytes(text + (newline ? name_length + 1 : 0), text + rest);
    if (flags & 1) bytes.resize(std::size_t(1201) * 1201 * 2, '\0');
    return outcome_of([&] { dem::read_hgt_bytes(bytes, name, "input.hgt"); });
}

Outcome feed_hgt_zip(const std::uint8_t* data, std::size_t size) {
    const fs::path path = write_input("N00E011.hgt.zip", data, size);
    return outcome_of([&] { dem::read_hgt_zip(path); });
}

Outcome feed_geotiff(const std::uint8_t* data, std::size_t size) {
    const fs::path path = write_input("input.tif", data, size);
    return outcome_of([&] { dem::read_geotiff(path); });
}

Feed feed_for(const std::string& reader) {
    if (reader == "hgt") return feed_hgt;
    if (reader == "hgt_zip") return feed_hgt_zip;
    if (reader == "geotiff") return feed_geotiff;
    return nullptr;
}

}  // namespace ts::fuzz
