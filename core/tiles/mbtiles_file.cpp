#include "core/tiles/mbtiles_file.hpp"

#include <sqlite3.h>

#include <chrono>
#include <system_error>
#include <vector>

#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::tiles {
namespace fs = std::filesystem;

namespace {

// How long a write waits for another process's lock on the file before it fails.
constexpr int kBusyTimeoutMs = 10000;


double now_s() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void remove_with_journal(const fs::path& p) {
    std::error_code ec;
    for (const char* suffix : {"", "-wal", "-shm", "-journal"}) fs::remove(p.string() + suffix, ec);
}

}  // namespace

fs::path MbtilesFile::partial_path(const fs::path& file) { return file.string() + ".partial"; }

namespace {

// Whether an SQLite file has a row in `tiles` (false if it cannot be read or has no such table).
bool holds_tiles(const fs::path& file) {
    sqlite3* db = nullptr;
    bool any = false;
    if (sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READONLY | SQLITE_OPEN_NOMUTEX, nullptr) == SQLITE_OK) {
        sqlite3_stmt* q = nullptr;
        sqlite3_prepare_v2(db, "SELECT 1 FROM tiles LIMIT 1", -1, &q, nullptr);
        any = q && sqlite3_step(q) == SQLITE_ROW;
        sqlite3_finalize(q);
    }
    sqlite3_close(db);
    return any;
}

}  // namespace

std::optional<std::string> MbtilesFile::job_of(const fs::path& file) {
    sqlite3* db = nullptr;
    std::optional<std::string> job;
    if (sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READONLY | SQLITE_OPEN_NOMUTEX, nullptr) == SQLITE_OK) {
        sqlite3_stmt* q = nullptr;
        sqlite3_prepare_v2(db, "SELECT value FROM metadata WHERE name = 'terrashade_job'", -1, &q, nullptr);
        if (q && sqlite3_step(q) == SQLITE_ROW)
            if (const auto* text = sqlite3_column_text(q, 0)) job = reinterpret_cast<const char*>(text);
        sqlite3_finalize(q);
    }
    sqlite3_close(db);
    return job;
}

MbtilesFile::MbtilesFile(fs::path file, std::map<std::string, std::string> metadata, const std::string& job,
                         Existing existing)
    : file_(std::move(file)), partial_(partial_path(file_)), metadata_(std::move(metadata)) {
    metadata_["terrashade_job"] = job;
    const fs::path dir = file_.parent_path().empty() ? fs::path(".") : file_.parent_path();
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw input_error(file_.string(), "output directory does not exist");
    if (fs::is_directory(file_, ec)) throw input_error(file_.string(), "is a directory, expected an .mbtiles file");
    // One job per output, decided before anything is written.
    const bool resume = existing == Existing::resume;
    // --resume continues FILE.partial, else adds to FILE: that one must hold this job. A new run
    // replaces both.
    std::vector<fs::path> checked = {partial_, file_};
    if (resume) checked = {fs::exists(partial_, ec) ? partial_ : file_};
    for (const fs::path& p : checked) {
        if (!fs::exists(p, ec) || job_of(p) == job) continue;
        // FILE.partial of a run killed before its first commit: ours, and nothing in it.
        if (p == partial_ && !job_of(p) && !holds_tiles(p)) continue;
        const std::string holds = fs::exists(p, ec) && job_of(p) ? "holds tiles of another job (other options)"
                                                                  : "holds no terrashade tile job that can be read";
        if (resume) throw OccupiedOutputError({p.string(), holds, true, "it", "file"});
        if (existing == Existing::refuse) throw OccupiedOutputError({p.string(), holds, false, "it", "file"});
    }
    if (!resume) remove_with_journal(partial_);
    if (resume && !fs::exists(partial_) && fs::exists(file_)) {
        // Add to a finished file through a copy: FILE stays whole until the rename.
        fs::copy_file(file_, partial_, fs::copy_options::overwrite_existing, ec);
        if (ec) throw input_error(partial_.string(), "cannot copy " + file_.string() + ": " + ec.message());
    }
    if (sqlite3_open_v2(partial_.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX,
                        nullptr) != SQLITE_OK) {
        sqlite3_close(db_);
        db_ = nullptr;
        throw input_error(file_.string(), "cannot create the MBTiles file (is the directory writable?)");
    }
    // A reader of the growing file (a viewer, a progress probe, a resumed run's check) may hold
    // a lock for a moment: wait for it instead of failing the job ("database is locked" when a
    // reader had the file open as the journal mode was switched, seen in the interrupt test).
    sqlite3_busy_timeout(db_, kBusyTimeoutMs);
    try {
        // WAL: a commit is one append to the log, and a killed writer loses only the open batch.
        // synchronous=NORMAL is durable against a killed process (not a power cut).
        exec("PRAGMA journal_mode=WAL");
        exec("PRAGMA synchronous=NORMAL");
        exec("CREATE TABLE IF NOT EXISTS metadata (name TEXT, value TEXT)");
        exec("CREATE UNIQUE INDEX IF NOT EXISTS metadata_name ON metadata (name)");
        exec("CREATE TABLE IF NOT EXISTS tiles (zoom_level INTEGER, tile_column INTEGER, tile_row INTEGER, "
             "tile_data BLOB)");
        exec("CREATE UNIQUE INDEX IF NOT EXISTS tile_index ON tiles (zoom_level, tile_column, tile_row)");
        {
            sqlite3_stmt* q = nullptr;
            sqlite3_prepare_v2(db_, "SELECT value FROM metadata WHERE name = 'terrashade_job'", -1, &q, nullptr);
            std::string previous;
            bool found = false;
            if (q && sqlite3_step(q) == SQLITE_ROW) {
                found = true;
                if (const auto* text = sqlite3_column_text(q, 0)) previous = reinterpret_cast<const char*>(text);
            }
            sqlite3_finalize(q);
            if (found && previous != job)
                throw input_error(file_.string(),
                                  "these tiles were made with other options; use them again or start afresh instead of resuming");
        }
        {
            sqlite3_stmt* q = nullptr;
            sqlite3_prepare_v2(db_, "SELECT zoom_level, tile_column, tile_row FROM tiles", -1, &q, nullptr);
            while (q && sqlite3_step(q) == SQLITE_ROW) {
                const int z = sqlite3_column_int(q, 0);
                existing_.insert({z, sqlite3_column_int(q, 1), int(tms_row(z, sqlite3_column_int(q, 2)))});
            }
            sqlite3_finalize(q);
        }
        exec("BEGIN");
        sqlite3_stmt* m = nullptr;
        sqlite3_prepare_v2(db_, "INSERT OR REPLACE INTO metadata (name, value) VALUES (?, ?)", -1, &m, nullptr);
        for (const auto& [name, value] : metadata_) {
            sqlite3_bind_text(m, 1, name.c_str(), -1, SQLITE_TRANSIENT);
            sqlite3_bind_text(m, 2, value.c_str(), -1, SQLITE_TRANSIENT);
            sqlite3_step(m);
            sqlite3_reset(m);
        }
        sqlite3_finalize(m);
        exec("COMMIT");
        if (sqlite3_prepare_v2(db_, "INSERT OR REPLACE INTO tiles (zoom_level, tile_column, tile_row, tile_data) "
                                    "VALUES (?, ?, ?, ?)", -1, &insert_, nullptr) != SQLITE_OK)
            throw input_error(file_.string(), std::string("sqlite: ") + sqlite3_errmsg(db_));
        exec("BEGIN");
        batch_started_ = now_s();
    } catch (...) {
        sqlite3_finalize(insert_);
        sqlite3_close(db_);
        db_ = nullptr;
        throw;
    }
}

MbtilesFile::~MbtilesFile() {
    // Not finished (an error on the way): keep the committed tiles in FILE.partial for --resume.
    if (db_) {
        sqlite3_finalize(insert_);
        if (!finished_) sqlite3_exec(db_, "COMMIT", nullptr, nullptr, nullptr);
        sqlite3_close(db_);
    }
}

void MbtilesFile::exec(const char* sql) {
    char* err = nullptr;
    if (sqlite3_exec(db_, sql, nullptr, nullptr, &err) != SQLITE_OK) {
        const std::string message = err ? err : "unknown error";
        sqlite3_free(err);
        throw input_error(file_.string(), "sqlite: " + message + " (" + sql + ")");
    }
}

bool MbtilesFile::has(const TileId& t) const { return existing_.count({t.z, t.x, t.y}) != 0; }

void MbtilesFile::commit_batch() {
    exec("COMMIT");
    exec("BEGIN");
    in_batch_ = 0;
    batch_started_ = now_s();
}

void MbtilesFile::put(const TileId& t, std::vector<std::uint8_t> png) {
    const std::lock_guard lock(mutex_);
    sqlite3_bind_int(insert_, 1, t.z);
    sqlite3_bind_int(insert_, 2, t.x);
    sqlite3_bind_int64(insert_, 3, tms_row(t.z, t.y));
    sqlite3_bind_blob(insert_, 4, png.data(), int(png.size()), SQLITE_TRANSIENT);
    const int rc = sqlite3_step(insert_);
    sqlite3_reset(insert_);
    if (rc != SQLITE_DONE) throw input_error(file_.string(), std::string("sqlite: ") + sqlite3_errmsg(db_));
    if (++in_batch_ >= kBatchTiles || now_s() - batch_started_ > kBatchSeconds) commit_batch();
}

void MbtilesFile::finish() {
    const std::lock_guard lock(mutex_);
    exec("COMMIT");
    // Fold the log back and leave a single self-contained file.
    exec("PRAGMA wal_checkpoint(TRUNCATE)");
    exec("PRAGMA journal_mode=DELETE");
    sqlite3_finalize(insert_);
    insert_ = nullptr;
    sqlite3_close(db_);
    db_ = nullptr;
    finished_ = true;
    std::error_code ec;
    fs::rename(partial_, file_, ec);
    if (ec) throw input_error(file_.string(), "cannot rename " + partial_.string() + " into place: " + ec.message());
}

}  // namespace ts::tiles
