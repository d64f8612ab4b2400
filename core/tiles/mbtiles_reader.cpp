#include "core/tiles/mbtiles_reader.hpp"

#include <sqlite3.h>

#include "core/util/error.hpp"

namespace ts::tiles {
namespace {

// Finalizes a statement however the scope is left (a callback may throw mid-iteration).
struct Statement {
    sqlite3_stmt* q = nullptr;
    ~Statement() { sqlite3_finalize(q); }
};

}  // namespace

MbtilesReader::MbtilesReader(std::filesystem::path file) : file_(std::move(file)) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file_, ec)) throw input_error(file_.string(), "no such MBTiles file");
    if (sqlite3_open_v2(file_.c_str(), &db_, SQLITE_OPEN_READONLY | SQLITE_OPEN_NOMUTEX, nullptr) != SQLITE_OK) {
        sqlite3_close(db_);
        db_ = nullptr;
        throw input_error(file_.string(), "cannot open as SQLite");
    }
    sqlite3_stmt* q = nullptr;
    if (sqlite3_prepare_v2(db_, "SELECT name, value FROM metadata", -1, &q, nullptr) != SQLITE_OK) {
        sqlite3_finalize(q);
        sqlite3_close(db_);
        db_ = nullptr;
        throw input_error(file_.string(), "not an MBTiles file (no metadata table)");
    }
    while (sqlite3_step(q) == SQLITE_ROW) {
        const auto* name = sqlite3_column_text(q, 0);
        const auto* value = sqlite3_column_text(q, 1);
        if (name) metadata_[reinterpret_cast<const char*>(name)] = value ? reinterpret_cast<const char*>(value) : "";
    }
    sqlite3_finalize(q);
    tile_count();  // checks the tiles table
}

MbtilesReader::~MbtilesReader() { sqlite3_close_v2(db_); }

std::size_t MbtilesReader::tile_count() const {
    sqlite3_stmt* q = nullptr;
    if (sqlite3_prepare_v2(db_, "SELECT count(*) FROM tiles", -1, &q, nullptr) != SQLITE_OK) {
        sqlite3_finalize(q);
        throw input_error(file_.string(), "not an MBTiles file (no tiles table)");
    }
    std::size_t n = 0;
    if (sqlite3_step(q) == SQLITE_ROW) n = std::size_t(sqlite3_column_int64(q, 0));
    sqlite3_finalize(q);
    return n;
}

void MbtilesReader::for_each_tile(const std::function<void(const TileId&, std::span<const std::uint8_t>)>& f) const {
    Statement statement;
    sqlite3_prepare_v2(db_,
                       "SELECT zoom_level, tile_column, tile_row, tile_data FROM tiles "
                       "ORDER BY zoom_level, tile_column, tile_row",
                       -1, &statement.q, nullptr);
    sqlite3_stmt* q = statement.q;
    int rc = SQLITE_ROW;
    while (q && (rc = sqlite3_step(q)) == SQLITE_ROW) {
        TileId t;
        t.z = sqlite3_column_int(q, 0);
        t.x = sqlite3_column_int(q, 1);
        t.y = int(tms_row(t.z, sqlite3_column_int64(q, 2)));
        const auto* data = static_cast<const std::uint8_t*>(sqlite3_column_blob(q, 3));
        const int size = sqlite3_column_bytes(q, 3);
        f(t, std::span<const std::uint8_t>(data, std::size_t(size)));
    }
    if (rc != SQLITE_DONE) throw input_error(file_.string(), std::string("sqlite: ") + sqlite3_errmsg(db_));
}

}  // namespace ts::tiles
