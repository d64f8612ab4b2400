#include "core/util/atomic_file.hpp"

#include <atomic>
#include <random>
#include <string>
#include <system_error>
#include <unistd.h>

#include "core/util/error.hpp"

namespace ts {
namespace fs = std::filesystem;

namespace {
fs::path temporary_sibling(const fs::path& target) {
    // pid + a random tag keeps concurrent writers (tests, batch jobs) apart.
    std::random_device rd;
    const std::string tag = std::to_string(::getpid()) + "-" + std::to_string(rd() % 1000000);
    fs::path tmp = target;
    tmp.replace_filename("." + target.stem().string() + ".tmp-" + tag + target.extension().string());
    return tmp;
}
}  // namespace

void write_atomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
    const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
        throw input_error(target.string(), "output directory does not exist");
    }
    if (fs::is_directory(target, ec)) {
        throw input_error(target.string(), "is a directory, expected an output file name");
    }
    const fs::path tmp = temporary_sibling(target);
    try {
        write(tmp);
    } catch (...) {
        fs::remove(tmp, ec);
        throw;
    }
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw input_error(target.string(), "cannot write: " + ec.message());
    }
}

}  // namespace ts
