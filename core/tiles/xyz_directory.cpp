#include "core/tiles/xyz_directory.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"
#include "core/util/shard_marker.hpp"
#include "core/tiles/tile_viewer.hpp"

namespace ts::tiles {
namespace fs = std::filesystem;

namespace {

void write_bytes(const fs::path& target, const void* data, std::size_t n) {
    write_atomically(target, [&](const fs::path& tmp) {
        std::FILE* f = std::fopen(tmp.c_str(), "wb");
        if (!f) throw input_error(target.string(), std::string("cannot write (") + std::strerror(errno) + ")");
        const bool ok = std::fwrite(data, 1, n, f) == n;
        const int written_errno = errno;
        if (std::fclose(f) != 0 || !ok)
            throw input_error(target.string(), std::string("cannot write (") + std::strerror(ok ? errno : written_errno) + ")");
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

bool is_number(const std::string& s) {
    return !s.empty() && s.size() < 10 && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The files a tile job made in DIR, and only those: Z/X/Y.png tiles and their temporaries, the
// Z and X folders left empty, the shard marker, the viewer (tile_viewer.hpp), then the job file
// (last: until it goes, the tiles still left are its job's). A user's other files stay, and so do
// the folders holding them.
void remove_tile_job(const fs::path& dir) {
    std::error_code ec;
    for (const auto& zdir : fs::directory_iterator(dir, ec)) {
        if (!zdir.is_directory(ec) || !is_number(zdir.path().filename().string())) continue;
        for (const auto& xdir : fs::directory_iterator(zdir.path(), ec)) {
            if (!xdir.is_directory(ec) || !is_number(xdir.path().filename().string())) continue;
            for (const auto& f : fs::directory_iterator(xdir.path(), ec)) {
                const fs::path& p = f.path();
                const bool tile = p.extension() == ".png" && is_number(p.stem().string()) && f.is_regular_file(ec);
                if (tile || is_temporary(p)) fs::remove(p, ec);
            }
            fs::remove(xdir.path(), ec);  // only if empty
        }
        fs::remove(zdir.path(), ec);
    }
    fs::remove(dir / kShardMarkerFile, ec);
    for (const char* file : kViewerFiles) fs::remove(dir / file, ec);
    fs::remove(dir / XyzDirectory::kJobFile, ec);
}

}  // namespace

XyzDirectory::XyzDirectory(fs::path dir, const std::string& job, Existing existing, int z0, int z1)
    : dir_(std::move(dir)), job_(job) {
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (!fs::is_directory(dir_)) throw input_error(dir_.string(), "cannot create the output directory");
    const fs::path job_file = dir_ / kJobFile;
    const bool empty = fs::is_empty(dir_, ec);
    const bool same_job = fs::is_regular_file(job_file, ec) && read_text(job_file) == job;
    if (!empty && !same_job) {
        const bool has_job = fs::exists(job_file, ec);
        const std::string holds = has_job ? "holds tiles of another job (other options, " + std::string(kJobFile) + ")"
                                          : "is not empty and holds no terrashade tile job";
        if (existing == Existing::resume) throw OccupiedOutputError({dir_.string(), holds, true, "it", "folder"});
        if (existing == Existing::refuse) throw OccupiedOutputError({dir_.string(), holds, false, "its tiles", "folder"});
        // The viewer written at the end would replace a file of the user's own of the same name.
        if (!has_job)
            for (const char* file : kViewerFiles)
                if (fs::exists(dir_ / file, ec))
                    throw input_error(dir_.string(), std::string("holds a ") + file +
                                                         " of its own, which the tiles' viewer would replace: move it "
                                                         "or write the tiles to another folder");
        // The old job goes when the first new tile is written (claim): an error or an interrupt
        // during the shading, which can take long, leaves it as it was.
        if (::access(dir_.c_str(), W_OK | X_OK) != 0)
            throw input_error(dir_.string(), "cannot write in the output directory (not writable)");
        pending_clear_ = true;
        return;
    }
    if (same_job) {
        // A killed run's temporaries (this job's: the folder is this job's).
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
        if (!same_job) write_bytes(job_file, job.data(), job.size());
        else if (::access(dir_.c_str(), W_OK | X_OK) != 0) throw InputError("not writable");
    } catch (const InputError& e) {
        // Why, as the system says it: not writable, or full.
        const std::string what = e.what();
        const auto why = what.find("cannot write (");
        throw input_error(dir_.string(), "cannot write in the output directory" +
                                             (why == std::string::npos ? std::string(" (not writable)") : " " + what.substr(why + 13)));
    }
}

fs::path XyzDirectory::tile_path(const TileId& t) const {
    return dir_ / std::to_string(t.z) / std::to_string(t.x) / (std::to_string(t.y) + ".png");
}

bool XyzDirectory::has(const TileId& t) const {
    if (pending_clear_) return false;  // the old job's tiles are not this job's
    std::error_code ec;
    return fs::is_regular_file(tile_path(t), ec);
}

void XyzDirectory::claim() {
    std::call_once(claimed_, [this] {
        if (!pending_clear_) return;
        remove_tile_job(dir_);
        write_bytes(dir_ / kJobFile, job_.data(), job_.size());
        pending_clear_ = false;
    });
}

void XyzDirectory::finish() { claim(); }  // a job that wrote no tile still replaces the old one

void XyzDirectory::put(const TileId& t, std::vector<std::uint8_t> png) {
    claim();
    const fs::path p = tile_path(t);
    std::error_code ec;
    fs::create_directories(p.parent_path(), ec);  // concurrent callers: EEXIST is fine
    write_bytes(p, png.data(), png.size());
}

}  // namespace ts::tiles
