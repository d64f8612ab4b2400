#include "core/util/atomic_file.hpp"

#include <system_error>
#include <utility>

#include "core/util/error.hpp"
#include "core/util/temp_files.hpp"

namespace ts {
namespace fs = std::filesystem;

void write_atomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
    const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
        throw input_error(target.string(), "output directory does not exist");
    }
    if (fs::is_directory(target, ec)) {
        throw input_error(target.string(), "is a directory, expected an output file name");
    }
    const fs::path tmp = temp_files::sibling_for(target);
    temp_files::track(tmp);
    try {
        write(tmp);
    } catch (...) {
        fs::remove(tmp, ec);
        temp_files::forget(tmp);
        throw;
    }
    const std::pair<fs::path, fs::path> move{tmp, target};
    temp_files::commit({&move, 1});
}

}  // namespace ts
