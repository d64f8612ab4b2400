#pragma once
// The time-of-day page of a lightable tile set (docs/web-map.md): app/web's page and ES
// modules, embedded when terrashade is built, written beside the tiles as the set's viewer.
#include <string>
#include <string_view>
#include <vector>

#include "core/tiles/tile_set_info.hpp"

namespace ts::app {

struct EmbeddedFile {
    const char* name;       // as in app/web
    std::string_view text;
};

// map.html, map.mjs and the modules it imports (generated: scripts/cmake/embed_text.cmake).
const std::vector<EmbeddedFile>& lightable_page_files();

// The files a lightable set's folder gets, by name: index.html (map.html with MapLibre pinned on
// the CDN with Subresource Integrity, as every viewer, and the set's name in its title) and the
// modules beside it.
std::vector<std::pair<std::string, std::string>> lightable_viewer_files(const tiles::TileSetInfo& info);

}  // namespace ts::app
