#pragma once
// Tiles in one MBTiles 1.3 file (SQLite): `metadata` (name, format, bounds, center, minzoom,
// maxzoom, attribution, ...) and `tiles` with TMS rows and a unique index on
// (zoom_level, tile_column, tile_row).
//
// Crash safety: the file is built as FILE.partial (WAL journal, tiles committed in batches) and
// renamed onto FILE only when complete (WAL folded back, journal_mode DELETE), so an existing
// FILE is never half-overwritten. A run killed at any moment leaves FILE.partial with whole
// committed batches; --resume reopens it (or copies a finished FILE to it to add tiles) and
// redoes only the tiles not committed. The metadata row `terrashade_job` records the job.
//
// One job per output: FILE or FILE.partial that holds another job (or none that can be read)
// is refused unless the caller allows replacing it (FILE is then replaced only when the new
// file is complete); --resume continues only a FILE.partial (or FILE) of the same job.
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <tuple>

#include "core/tiles/tile_sink.hpp"

struct sqlite3;
struct sqlite3_stmt;

namespace ts::tiles {

class MbtilesFile final : public TileSink {
public:
    // `metadata`: name -> value, written at creation (and again by finish). Throws
    // ts::InputError when FILE cannot be written, or with `resume` when the job differs.
    enum class Existing { refuse, resume, overwrite };
    MbtilesFile(std::filesystem::path file, std::map<std::string, std::string> metadata, const std::string& job,
                Existing existing);
    ~MbtilesFile() override;
    bool has(const TileId& t) const override;
    void put(const TileId& t, std::vector<std::uint8_t> png) override;
    void finish() override;

    static std::filesystem::path partial_path(const std::filesystem::path& file);
    // The `terrashade_job` of an MBTiles file; nullopt if it has none or cannot be read.
    static std::optional<std::string> job_of(const std::filesystem::path& file);
    // Tiles per committed batch (also committed after kBatchSeconds).
    static constexpr int kBatchTiles = 64;
    static constexpr double kBatchSeconds = 1.0;

private:
    void exec(const char* sql);
    void commit_batch();

    std::filesystem::path file_, partial_;
    std::map<std::string, std::string> metadata_;
    ::sqlite3* db_ = nullptr;
    ::sqlite3_stmt* insert_ = nullptr;
    std::set<std::tuple<int, int, int>> existing_;  // (z, x, XYZ y) found on resume
    std::mutex mutex_;
    int in_batch_ = 0;
    double batch_started_ = 0;
    bool finished_ = false;
};

}  // namespace ts::tiles
