#include "core/tiles/tile_merge.hpp"

#include <charconv>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <tuple>
#include <utility>

#include "core/tiles/mbtiles_file.hpp"
#include "core/tiles/mbtiles_reader.hpp"
#include "core/tiles/tile_viewer.hpp"
#include "core/tiles/xyz_directory.hpp"
#include "core/util/error.hpp"
#include "core/util/shard.hpp"
#include "core/util/shard_marker.hpp"
#include "core/util/temp_files.hpp"

namespace ts::tiles {
namespace fs = std::filesystem;

namespace {

constexpr const char* kShardKey = "terrashade_shard";

using TileKey = std::tuple<int, int, int>;

std::string tile_name(const TileKey& k) {
    return std::to_string(std::get<0>(k)) + "/" + std::to_string(std::get<1>(k)) + "/" + std::to_string(std::get<2>(k));
}

std::vector<std::string> names_of(const std::vector<fs::path>& paths) {
    std::vector<std::string> names;
    for (const fs::path& p : paths) names.push_back(p.string());
    return names;
}

// Tiles seen so far: their content hash and the shard they came from.
class SeenTiles {
public:
    // True if the tile is new; false for an identical duplicate; throws for a different one.
    bool add(const TileKey& key, std::uint64_t hash, const std::string& shard) {
        const auto [it, fresh] = seen_.emplace(key, std::make_pair(hash, shard));
        if (fresh) return true;
        if (it->second.first != hash)
            throw input_error(shard, "tile " + tile_name(key) + " is also in " + it->second.second +
                                         " with other bytes: these are not shards of one job");
        return false;
    }

private:
    std::map<TileKey, std::pair<std::uint64_t, std::string>> seen_;
};

bool parse_uint(const std::string& s, int& out) {
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return !s.empty() && ec == std::errc() && p == s.data() + s.size() && out >= 0;
}

// The tiles of an XYZ folder: DIR/z/x/y.png with numeric z, x, y (temporary files, the job file
// and the shard marker are not tiles).
std::map<TileKey, fs::path> xyz_tiles(const fs::path& dir) {
    std::map<TileKey, fs::path> tiles;
    for (const auto& zd : fs::directory_iterator(dir)) {
        int z = 0;
        if (!zd.is_directory() || !parse_uint(zd.path().filename().string(), z)) continue;
        for (const auto& xd : fs::directory_iterator(zd.path())) {
            int x = 0;
            if (!xd.is_directory() || !parse_uint(xd.path().filename().string(), x)) continue;
            for (const auto& f : fs::directory_iterator(xd.path())) {
                int y = 0;
                if (f.is_regular_file() && f.path().extension() == ".png" && parse_uint(f.path().stem().string(), y))
                    tiles[{z, x, y}] = f.path();
            }
        }
    }
    return tiles;
}

std::string read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) throw input_error(p.string(), "cannot read");
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// A hard link if the file system allows (no copy of the bytes), else a copy.
void link_or_copy(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::create_hard_link(from, to, ec);
    if (!ec) return;
    fs::copy_file(from, to, ec);
    if (ec) throw input_error(to.string(), "cannot write: " + ec.message());
}

}  // namespace

std::uint64_t content_hash(const std::uint8_t* data, std::size_t size) {
    std::uint64_t h = 1469598103934665603ull;
    for (std::size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ull;
    return h;
}

MergeStats merge_mbtiles(const std::vector<fs::path>& shards, const fs::path& out) {
    // Every check before writing anything.
    std::vector<std::unique_ptr<MbtilesReader>> readers;
    std::vector<std::optional<Shard>> ids;
    for (const fs::path& p : shards) {
        readers.push_back(std::make_unique<MbtilesReader>(p));
        const auto& m = readers.back()->metadata();
        const auto it = m.find(kShardKey);
        ids.push_back(it == m.end() ? std::nullopt : std::optional<Shard>(parse_shard(it->second, p.string() + ":")));
    }
    check_complete_shard_set(names_of(shards), ids);
    std::map<std::string, std::string> metadata = readers.front()->metadata();
    metadata.erase(kShardKey);
    for (std::size_t i = 1; i < readers.size(); ++i) {
        std::map<std::string, std::string> m = readers[i]->metadata();
        m.erase(kShardKey);
        if (m != metadata) {
            std::string key;
            for (const auto& [name, value] : m)
                if (!metadata.count(name) || metadata.at(name) != value) key = name;
            for (const auto& [name, value] : metadata)
                if (!m.count(name)) key = name;
            throw input_error(shards[i].string(), "metadata '" + key + "' differs from " + shards.front().string() +
                                                      "'s: not shards of one job");
        }
    }
    const auto job = metadata.find("terrashade_job");
    if (job == metadata.end()) throw input_error(shards.front().string(), "has no terrashade_job metadata");
    const std::string job_text = job->second;
    metadata.erase(job);

    // Built as TMP (MbtilesFile writes TMP.partial and renames it onto TMP), then TMP onto OUT.
    const fs::path tmp = temp_files::sibling_for(out);
    const fs::path partial = MbtilesFile::partial_path(tmp);
    const std::vector<fs::path> scratch = {tmp, partial, partial.string() + "-wal", partial.string() + "-shm",
                                           partial.string() + "-journal"};
    for (const fs::path& p : scratch) temp_files::track(p);
    auto drop_scratch = [&] {
        std::error_code ec;
        for (const fs::path& p : scratch) fs::remove(p, ec), temp_files::forget(p);
    };
    MergeStats stats;
    stats.shards = shards.size();
    try {
        {
            MbtilesFile sink(tmp, metadata, job_text, MbtilesFile::Existing::refuse);
            SeenTiles seen;
            for (std::size_t i = 0; i < readers.size(); ++i)
                readers[i]->for_each_tile([&](const TileId& t, std::span<const std::uint8_t> png) {
                    if (seen.add({t.z, t.x, t.y}, content_hash(png.data(), png.size()), shards[i].string())) {
                        sink.put(t, std::vector<std::uint8_t>(png.begin(), png.end()));
                        ++stats.tiles;
                    } else {
                        ++stats.duplicates;
                    }
                });
            sink.finish();
        }
        for (std::size_t i = 1; i < scratch.size(); ++i) temp_files::forget(scratch[i]);
        const std::pair<fs::path, fs::path> move{tmp, out};
        temp_files::commit({&move, 1});
    } catch (...) {
        drop_scratch();
        throw;
    }
    return stats;
}

MergeStats merge_xyz(const std::vector<fs::path>& shards, const fs::path& out) {
    std::vector<std::optional<Shard>> ids;
    std::string job_text;
    for (const fs::path& p : shards) {
        std::error_code ec;
        if (!fs::is_directory(p, ec)) throw input_error(p.string(), "no such tile folder");
        const fs::path job_file = p / XyzDirectory::kJobFile;
        if (!fs::exists(job_file)) throw input_error(p.string(), "is not a terrashade tile folder (no job file)");
        const std::string job = read_bytes(job_file);
        if (&p == &shards.front()) job_text = job;
        else if (job != job_text)
            throw input_error(p.string(), "was made with other options than " + shards.front().string() +
                                              ": not shards of one job");
        ids.push_back(read_shard_marker(p));
    }
    check_complete_shard_set(names_of(shards), ids);
    // The viewer (tiles.json, the page, the legend) is the same in every shard of one job: the
    // merged folder takes the first shard's, as a single run would have written it.
    std::vector<const char*> viewer;
    for (const char* file : kViewerFiles) {
        std::error_code ec;
        const bool in_first = fs::is_regular_file(shards.front() / file, ec);
        for (const fs::path& p : shards) {
            const bool here = fs::is_regular_file(p / file, ec);
            if (here != in_first || (here && read_bytes(p / file) != read_bytes(shards.front() / file)))
                throw input_error(p.string(), std::string("has another ") + file + " than " + shards.front().string() +
                                                  ": not finished shards of one job");
        }
        if (in_first) viewer.push_back(file);
    }
    std::error_code ec;
    if (fs::exists(out, ec) && !(fs::is_directory(out, ec) && fs::is_empty(out, ec)))
        throw input_error(out.string(), "exists: merge writes a new tile folder (remove it or choose another)");
    const fs::path parent = out.parent_path().empty() ? fs::path(".") : out.parent_path();
    if (!fs::is_directory(parent, ec)) throw input_error(out.string(), "output directory does not exist");

    // Which tile comes from where, and the duplicates checked, before writing.
    MergeStats stats;
    stats.shards = shards.size();
    std::map<TileKey, fs::path> plan;
    SeenTiles seen;
    for (const fs::path& p : shards)
        for (auto& [key, file] : xyz_tiles(p)) {
            const std::string bytes = read_bytes(file);
            if (seen.add(key, content_hash(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()),
                         p.string()))
                plan.emplace(key, file);
            else
                ++stats.duplicates;
        }
    stats.tiles = plan.size();

    // The folder tree under a temporary name; an interrupt removes it from the leaves up.
    const fs::path tmp = temp_files::sibling_for(out);
    std::vector<fs::path> dirs;  // x folders, then z folders, then the root
    {
        std::map<std::pair<int, int>, bool> xs;
        std::map<int, bool> zs;
        for (const auto& [key, file] : plan) xs[{std::get<0>(key), std::get<1>(key)}] = zs[std::get<0>(key)] = true;
        for (const auto& [zx, unused] : xs) dirs.push_back(tmp / std::to_string(zx.first) / std::to_string(zx.second));
        for (const auto& [z, unused] : zs) dirs.push_back(tmp / std::to_string(z));
        dirs.push_back(tmp);
    }
    for (const fs::path& d : dirs) temp_files::track_directory(d);
    try {
        for (auto it = dirs.rbegin(); it != dirs.rend(); ++it)
            if (!fs::create_directory(*it, ec) && ec) throw input_error(it->string(), "cannot create: " + ec.message());
        for (const auto& [key, file] : plan)
            link_or_copy(file, tmp / std::to_string(std::get<0>(key)) / std::to_string(std::get<1>(key)) /
                                   (std::to_string(std::get<2>(key)) + ".png"));
        for (const char* file : viewer) link_or_copy(shards.front() / file, tmp / file);
        link_or_copy(shards.front() / XyzDirectory::kJobFile, tmp / XyzDirectory::kJobFile);
        if (fs::exists(out, ec)) fs::remove(out, ec);  // empty, checked above
        fs::rename(tmp, out, ec);
        if (ec) throw input_error(out.string(), "cannot rename " + tmp.string() + " into place: " + ec.message());
        for (const fs::path& d : dirs) temp_files::forget_directory(d);
    } catch (...) {
        fs::remove_all(tmp, ec);
        for (const fs::path& d : dirs) temp_files::forget_directory(d);
        throw;
    }
    return stats;
}

}  // namespace ts::tiles
