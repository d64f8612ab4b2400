#pragma once
// Where finished tiles go: an XYZ directory (xyz_directory.hpp) or one MBTiles file
// (mbtiles_file.hpp). Both make every tile durable on its own (rename, committed batch), so a
// run killed at any moment leaves only whole tiles, and `has` tells a resumed run which.
#include <cstdint>
#include <vector>

#include "core/tiles/web_mercator.hpp"

namespace ts::tiles {

class TileSink {
public:
    virtual ~TileSink() = default;
    // True if the tile is already stored whole (from an earlier run being resumed).
    virtual bool has(const TileId& t) const = 0;
    // Stores one encoded tile. Thread-safe.
    virtual void put(const TileId& t, std::vector<std::uint8_t> png) = 0;
    // Every tile is in: make the result final (an MBTiles file is renamed into place).
    virtual void finish() = 0;
};

}  // namespace ts::tiles
