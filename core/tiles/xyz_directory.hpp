#pragma once
// Tiles as DIR/z/x/y.png, each written under a temporary name and renamed into place, so a tile
// file that exists is complete. DIR/.terrashade-tiles.json records the job (style, light, sizes)
// so --resume refuses to mix tiles of different jobs.
#include <filesystem>
#include <string>

#include "core/tiles/tile_sink.hpp"

namespace ts::tiles {

class XyzDirectory final : public TileSink {
public:
    // Creates DIR if needed and checks it is writable (ts::InputError otherwise). With `resume`,
    // an existing job file must equal `job`; temporary files of a killed run are removed.
    XyzDirectory(std::filesystem::path dir, const std::string& job, bool resume, int z0, int z1);
    bool has(const TileId& t) const override;
    void put(const TileId& t, std::vector<std::uint8_t> png) override;
    void finish() override {}

    std::filesystem::path tile_path(const TileId& t) const;
    static constexpr const char* kJobFile = ".terrashade-tiles.json";

private:
    std::filesystem::path dir_;
};

}  // namespace ts::tiles
