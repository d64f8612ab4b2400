#pragma once
// Tiles as DIR/z/x/y.png, each written under a temporary name and renamed into place, so a tile
// file that exists is complete. DIR/.terrashade-tiles.json records the job (style, light, sizes).
//
// One job per folder: the job file is written only once this job owns the folder (it was empty
// or missing, it already holds this job, or the caller allowed replacing the old job, whose
// tiles are removed first). So every tile in a folder belongs to the job its job file names,
// and a resumed run can keep them all: an interrupted run of another job can never have left
// tiles under this job's description.
#include <atomic>
#include <filesystem>
#include <mutex>
#include <string>

#include "core/tiles/tile_sink.hpp"

namespace ts::tiles {

class XyzDirectory final : public TileSink {
public:
    // What a run may do with a folder that holds something else than `job`.
    enum class Existing { refuse, resume, overwrite };
    // Creates DIR if needed and checks it is writable (ts::InputError otherwise). A folder that
    // is not empty and holds another job (or none that can be read) is refused, unless
    // `overwrite`: then the old job's files (tiles DIR/Z/X/Y.png, temporaries, job, shard and
    // viewer files, the folders left empty) are removed and nothing else, when the first new
    // tile is written (or at finish): until then, an error or an interrupt leaves them as they
    // were. A folder without a job file that holds a file named as one of the viewer's is refused
    // even so. With `resume` the job file must equal `job`. Temporary files of a killed run are
    // removed.
    XyzDirectory(std::filesystem::path dir, const std::string& job, Existing existing, int z0, int z1);
    bool has(const TileId& t) const override;
    void put(const TileId& t, std::vector<std::uint8_t> png) override;
    void finish() override;

    std::filesystem::path tile_path(const TileId& t) const;
    static constexpr const char* kJobFile = ".terrashade-tiles.json";

private:
    void claim();  // --overwrite: the old job's files go, this job's file is written; once

    std::filesystem::path dir_;
    std::string job_;
    std::atomic<bool> pending_clear_{false};
    std::once_flag claimed_;
};

}  // namespace ts::tiles
