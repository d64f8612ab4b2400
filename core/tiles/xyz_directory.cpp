#include "core/tiles/xyz_directory.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"

namespace ts::tiles {
namespace fs = std::filesystem;

namespace {

void write_bytes(const fs::path& target, const void* data, std::size_t n) {
    write_atomically(target, [&](const fs::path& tmp) {
        std::FILE* f = std::fopen(tmp.c_str(), "wb");
        if (!f) throw input_error(target.string(), "cannot write");
        const bool ok = std::fwrite(data, 1, n, f) == n;
        if (std::fclose(f) != 0 || !ok) throw input_error(target.string(), "cannot write (disk full?)");
    });
}

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// write_atomically's temporary names: ".<stem>.tmp-<pid>-<tag><ext>".
bool is_temporary(const fs::path& p) {
    const std::string name = p.filename().string();
    return name.size() > 1 && name[0] == '.' && name.find(".tmp-") != std::string::npos;
}

}  // namespace

XyzDirectory::XyzDirectory(fs::path dir, const std::string& job, bool resume, int z0, int z1) : dir_(std::move(dir)) {
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (!fs::is_directory(dir_)) throw input_error(dir_.string(), "cannot create the output directory");
    const fs::path job_file = dir_ / kJobFile;
    if (resume && fs::exists(job_file)) {
        if (read_text(job_file) != job)
            throw input_error(dir_.string(), "--resume: these tiles were made with other options (" +
                                                 job_file.string() + "); use them again or drop --resume");
        for (int z = z0; z <= z1; ++z) {
            const fs::path zdir = dir_ / std::to_string(z);
            if (!fs::is_directory(zdir, ec)) continue;
            for (const auto& xdir : fs::directory_iterator(zdir, ec))
                for (const auto& f : fs::directory_iterator(xdir.path(), ec))
                    if (is_temporary(f.path())) fs::remove(f.path(), ec);
        }
    }
    // Also the writability probe: an unwritable DIR fails here, before any shading.
    try {
        write_bytes(job_file, job.data(), job.size());
    } catch (const InputError&) {
        throw input_error(dir_.string(), "the output directory is not writable");
    }
}

fs::path XyzDirectory::tile_path(const TileId& t) const {
    return dir_ / std::to_string(t.z) / std::to_string(t.x) / (std::to_string(t.y) + ".png");
}

bool XyzDirectory::has(const TileId& t) const {
    std::error_code ec;
    return fs::is_regular_file(tile_path(t), ec);
}

void XyzDirectory::put(const TileId& t, std::vector<std::uint8_t> png) {
    const fs::path p = tile_path(t);
    std::error_code ec;
    fs::create_directories(p.parent_path(), ec);  // concurrent callers: EEXIST is fine
    write_bytes(p, png.data(), png.size());
}

}  // namespace ts::tiles
