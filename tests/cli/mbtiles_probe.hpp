#pragma once
// The tiles an MBTiles file being written has committed so far, read as a concurrent reader
// (a user, a tile server) would: the tiles and interrupt tests watch an export with it.
#include <sqlite3.h>

#include <cstddef>
#include <filesystem>
#include <string>

namespace ts::cli_test {

// Tiles committed to an MBTiles file (its WAL log included), 0 if it cannot be read yet.
inline std::size_t committed_tiles(const std::string& file) {
    if (!std::filesystem::exists(file)) return 0;
    sqlite3* db = nullptr;
    std::size_t n = 0;
    if (sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK) {
        sqlite3_busy_timeout(db, 100);
        sqlite3_stmt* q = nullptr;
        if (sqlite3_prepare_v2(db, "SELECT count(*) FROM tiles", -1, &q, nullptr) == SQLITE_OK &&
            sqlite3_step(q) == SQLITE_ROW)
            n = std::size_t(sqlite3_column_int64(q, 0));
        sqlite3_finalize(q);
    }
    sqlite3_close(db);
    return n;
}

}  // namespace ts::cli_test
