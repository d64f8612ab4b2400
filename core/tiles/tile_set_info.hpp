#pragma once
// What a tile set says about itself to its readers: its name, what it shows, whose data it is,
// where and at which zooms it has tiles, and its legend picture if it has one. One description
// feeds both the MBTiles metadata table and the TileJSON written beside an XYZ folder
// (tile_viewer.hpp), so the two never disagree.
#include <map>
#include <string>

#include "core/tiles/dem_footprint.hpp"

namespace ts::tiles {

struct TileSetInfo {
    std::string name;         // plain text
    std::string description;  // plain text
    std::string attribution;  // shown by map clients, which may read it as HTML (links)
    LonLatBox bounds;         // the terrain's footprint
    int minzoom = 0, maxzoom = 0;
    int tile_size = 256;
    std::string legend_file;  // the legend picture beside the tiles ("" = none)
    std::string legend_alt;   // what it shows, plain text
};

// "<escaped>" for JSON and HTML text.
std::string json_string(const std::string& text);
std::string html_text(const std::string& text);

// The MBTiles 1.3 metadata rows the description fills: name, format, bounds, center, minzoom,
// maxzoom, attribution, type, version, description. (1.3 has no legend row, and an MBTiles file
// carries no picture beside it.)
std::map<std::string, std::string> mbtiles_metadata(const TileSetInfo& info);

// TileJSON 3.0.0 of an XYZ folder, for a file beside the tiles. The spec asks for absolute tile
// URLs, which a folder cannot know before it is served: the one endpoint is "{z}/{x}/{y}.png",
// relative to the TileJSON's own URL, and the legend's picture is relative the same way (the
// viewer page resolves both). Adds "tile_size" (the spec has none; MapLibre needs it for 512).
std::string tilejson_text(const TileSetInfo& info);

}  // namespace ts::tiles
