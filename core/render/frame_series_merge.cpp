#include "core/render/frame_series_merge.hpp"

#include <charconv>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"
#include "core/util/shard.hpp"
#include "core/util/shard_marker.hpp"
#include "core/util/temp_files.hpp"

namespace ts::render {
namespace fs = std::filesystem;

namespace {

struct Row {
    std::string line, file;
    fs::path from;  // the shard folder
};

std::string read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) throw input_error(p.string(), "cannot read");
    return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

FrameMergeStats merge_frame_series(const std::vector<fs::path>& shards, const fs::path& out) {
    std::vector<std::string> names;
    std::vector<std::optional<Shard>> ids;
    std::string header;
    std::map<std::size_t, Row> rows;  // frame number -> row
    for (const fs::path& dir : shards) {
        names.push_back(dir.string());
        const fs::path csv = dir / "times.csv";
        std::ifstream in(csv);
        if (!in) throw input_error(dir.string(), "is not a relight folder (no times.csv)");
        ids.push_back(read_shard_marker(dir));
        std::string line;
        std::getline(in, line);
        if (header.empty()) header = line;
        else if (line != header)
            throw input_error(csv.string(), "has other columns than " + shards.front().string() + "'s (another format?)");
        int number = 1;
        while (std::getline(in, line)) {
            ++number;
            if (line.empty()) continue;
            const auto c1 = line.find(','), c2 = line.find(',', c1 == std::string::npos ? c1 : c1 + 1);
            std::size_t frame = 0;
            const auto [p, ec] = std::from_chars(line.data(), line.data() + (c1 == std::string::npos ? 0 : c1), frame);
            if (c2 == std::string::npos || ec != std::errc() || p != line.data() + c1)
                throw input_error(csv.string(), "line " + std::to_string(number) + ": not frame,file,...");
            Row row{line, line.substr(c1 + 1, c2 - c1 - 1), dir};
            if (row.file.find('/') != std::string::npos || row.file.starts_with("."))
                throw input_error(csv.string(), "line " + std::to_string(number) + ": a frame file outside the folder");
            const auto [it, fresh] = rows.emplace(frame, row);
            if (!fresh && (it->second.line != row.line ||
                           read_bytes(it->second.from / row.file) != read_bytes(dir / row.file)))
                throw input_error(csv.string(), "frame " + std::to_string(frame) + " is also in " +
                                                    it->second.from.string() + ", different: not shards of one series");
        }
    }
    check_complete_shard_set(names, ids);
    std::size_t expected = 0;
    for (const auto& [frame, row] : rows) {
        if (frame != expected) throw InputError("merge: frame " + std::to_string(expected) + " is in no shard");
        std::error_code ec;
        if (!fs::is_regular_file(row.from / row.file, ec))
            throw input_error((row.from / row.file).string(), "listed in times.csv but missing");
        ++expected;
    }
    std::error_code ec;
    if (fs::exists(out, ec) && !(fs::is_directory(out, ec) && fs::is_empty(out, ec)))
        throw input_error(out.string(), "exists: merge writes a new folder (remove it or choose another)");
    const fs::path parent = out.parent_path().empty() ? fs::path(".") : out.parent_path();
    if (!fs::is_directory(parent, ec)) throw input_error(out.string(), "output directory does not exist");

    const fs::path tmp = temp_files::sibling_for(out);
    temp_files::track_directory(tmp);
    try {
        fs::create_directory(tmp);
        std::string csv = header + "\n";
        for (const auto& [frame, row] : rows) {
            const fs::path to = tmp / row.file;
            fs::create_hard_link(row.from / row.file, to, ec);
            if (ec) {
                fs::copy_file(row.from / row.file, to, ec);
                if (ec) throw input_error(to.string(), "cannot write: " + ec.message());
            }
            csv += row.line + "\n";
        }
        {
            std::ofstream f(tmp / "times.csv", std::ios::binary);
            f << csv;
            if (!f.flush()) throw input_error((tmp / "times.csv").string(), "cannot write (disk full?)");
        }
        if (fs::exists(out, ec)) fs::remove(out, ec);
        fs::rename(tmp, out, ec);
        if (ec) throw input_error(out.string(), "cannot rename " + tmp.string() + " into place: " + ec.message());
        temp_files::forget_directory(tmp);
    } catch (...) {
        fs::remove_all(tmp, ec);
        temp_files::forget_directory(tmp);
        throw;
    }
    return {shards.size(), rows.size()};
}

}  // namespace ts::render
