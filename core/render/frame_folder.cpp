#include "core/render/frame_folder.hpp"

#include <system_error>
#include <vector>

#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"
#include "core/util/shard_marker.hpp"

namespace ts::render {
namespace fs = std::filesystem;

bool is_frame_series_file(const std::string& name) {
    if (name == "times.csv" || name == kShardMarkerFile) return true;
    // write_atomically's temporaries: ".<stem>.tmp-<pid>-<tag><ext>".
    const bool temporary = name.starts_with(".") && name.find(".tmp-") != std::string::npos;
    const std::string base = temporary ? name.substr(1) : name;
    if (temporary && base.starts_with("times")) return true;
    if (!base.starts_with("frame_")) return false;
    for (const char* ext : {".png", ".tif", ".exr"})
        if (base.ends_with(ext)) return true;
    return false;
}

void check_frame_folder(const fs::path& dir, bool overwrite) {
    std::error_code ec;
    if (!fs::exists(dir, ec)) return;
    if (!fs::is_directory(dir, ec)) throw input_error(dir.string(), "is a file; a frame series goes to a folder");
    if (!overwrite && !fs::is_empty(dir, ec))
        throw OccupiedOutputError(
            {dir.string(), "is not empty (another frame series?)", false, "its frames and times.csv", "folder"});
}

bool claim_frame_folder(const fs::path& dir, bool overwrite) {
    check_frame_folder(dir, overwrite);
    std::error_code ec;
    const bool existed = fs::exists(dir, ec);
    if (existed && !fs::is_empty(dir, ec)) {
        std::vector<fs::path> old;
        for (const auto& e : fs::directory_iterator(dir, ec))
            if (e.is_regular_file(ec) && is_frame_series_file(e.path().filename().string())) old.push_back(e.path());
        // times.csv first: until the frames are gone it would list files no longer there.
        for (const fs::path& p : old)
            if (p.filename() == "times.csv") fs::remove(p, ec);
        for (const fs::path& p : old) fs::remove(p, ec);
    }
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir, ec)) throw input_error(dir.string(), "cannot create the output directory");
    return !existed;
}

}  // namespace ts::render
