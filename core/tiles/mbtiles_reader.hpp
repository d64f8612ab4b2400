#pragma once
// An MBTiles file opened read-only: its metadata and its tiles (XYZ rows), for `merge` and the
// tests. SQLite's own locking lets it read a file another process is not writing.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <span>
#include <string>

#include "core/tiles/web_mercator.hpp"

struct sqlite3;

namespace ts::tiles {

class MbtilesReader {
public:
    // ts::InputError if the file is missing or not an MBTiles file (no metadata or tiles table).
    explicit MbtilesReader(std::filesystem::path file);
    ~MbtilesReader();
    MbtilesReader(const MbtilesReader&) = delete;
    MbtilesReader& operator=(const MbtilesReader&) = delete;

    const std::map<std::string, std::string>& metadata() const { return metadata_; }
    std::size_t tile_count() const;
    // Every tile in (zoom, column, TMS row) order, with y as an XYZ row.
    void for_each_tile(const std::function<void(const TileId&, std::span<const std::uint8_t>)>& f) const;

private:
    std::filesystem::path file_;
    ::sqlite3* db_ = nullptr;
    std::map<std::string, std::string> metadata_;
};

}  // namespace ts::tiles
