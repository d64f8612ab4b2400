#pragma once
// The viewer written beside every XYZ tile set: its TileJSON (tile_set_info.hpp), a MapLibre GL
// JS page that reads it, and a legend picture for the styles whose colours stand for values.
// The page loads MapLibre from a CDN at one pinned version with Subresource Integrity (the
// user's folder has no node_modules), shows the tiles on a plain background with navigation,
// scale, the attribution and the legend, and says how to serve the folder when it is opened
// from file:// (browsers do not let MapLibre fetch tiles from there).
#include <array>
#include <string>

#include "core/tiles/tile_set_info.hpp"

namespace ts::tiles {

constexpr const char* kTileJsonFile = "tiles.json";
constexpr const char* kViewerPageFile = "index.html";
constexpr const char* kLegendFile = "legend.png";
// A lightable set's sky tables and site (lightable_sky.hpp).
constexpr const char* kLightableFile = "lightable.json";
// Every file of the viewer: a tile job owns them as it owns its tiles (removed with its tiles,
// copied by a merge).
// A lightable set's page imports its modules from beside it (lightable_page.hpp).
constexpr std::array<const char*, 10> kViewerFiles = {kTileJsonFile,   kViewerPageFile, kLegendFile,     kLightableFile,
                                                      "map.mjs",       "relight.mjs",   "relight_worker.mjs",
                                                      "png.mjs",       "tileset.mjs",   "sun_position.mjs"};

// The MapLibre GL JS release the page loads: the version of docs/tiles/package-lock.json, and
// the sha384 of its dist files there (the bytes the CDN serves for that version).
constexpr const char* kMaplibreVersion = "5.20.0";
constexpr const char* kMaplibreJsUrl = "https://unpkg.com/maplibre-gl@5.20.0/dist/maplibre-gl.js";
constexpr const char* kMaplibreJsSri = "sha384-+b8JF3Yd8bok2XtnwqevHSNq6n3Ws6nAFAk8dKVW6miRkFG48p2x2iOUq1nStldl";
constexpr const char* kMaplibreCssUrl = "https://unpkg.com/maplibre-gl@5.20.0/dist/maplibre-gl.css";
constexpr const char* kMaplibreCssSri = "sha384-MGCxhspF/+ufueUgol3FDkiAYQbpSNRhBT0VWHJt64U8qIy9qlnXWx8LAbj6niPH";

// The page (index.html). Its title and header carry the tile set's name and description, so
// they show even where tiles.json cannot be read (file://); the rest comes from tiles.json.
std::string viewer_page_html(const TileSetInfo& info);

}  // namespace ts::tiles
