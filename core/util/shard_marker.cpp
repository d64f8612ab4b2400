#include "core/util/shard_marker.hpp"

#include <fstream>
#include <string>
#include <system_error>

#include "core/util/atomic_file.hpp"
#include "core/util/error.hpp"

namespace ts {

void write_shard_marker(const std::filesystem::path& dir, const Shard& shard) {
    const std::filesystem::path path = dir / kShardMarkerFile;
    write_atomically(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp);
        out << shard_text(shard) << "\n";
        if (!out.flush()) throw input_error(path.string(), "cannot write (disk full?)");
    });
}

void remove_shard_marker(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::remove(dir / kShardMarkerFile, ec);
}

std::optional<Shard> read_shard_marker(const std::filesystem::path& dir) {
    const std::filesystem::path path = dir / kShardMarkerFile;
    std::ifstream in(path);
    if (!in) return std::nullopt;
    std::string line;
    std::getline(in, line);
    return parse_shard(line, path.string() + ":");
}

}  // namespace ts
