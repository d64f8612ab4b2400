#include "app/lightable_page.hpp"

#include <stdexcept>

#include "core/tiles/tile_viewer.hpp"

namespace ts::app {

std::vector<std::pair<std::string, std::string>> lightable_viewer_files(const tiles::TileSetInfo& info) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const EmbeddedFile& f : lightable_page_files()) {
        std::string text(f.text);
        if (std::string_view(f.name) == "map.html") {
            const std::string module = "<script type=\"module\" src=\"map.mjs\"></script>";
            const auto at = text.find(module);
            if (at == std::string::npos) throw std::logic_error("app/web/map.html: no map.mjs script");
            text.insert(at, std::string("<script>window.TERRASHADE_MAPLIBRE = {js: '") + tiles::kMaplibreJsUrl +
                                "', jsIntegrity: '" + tiles::kMaplibreJsSri + "', css: '" + tiles::kMaplibreCssUrl +
                                "', cssIntegrity: '" + tiles::kMaplibreCssSri + "'};</script>\n");
            const std::string title = "<title>terrashade: relief by time of day</title>";
            if (const auto t = text.find(title); t != std::string::npos)
                text.replace(t, title.size(), "<title>" + tiles::html_text(info.name) + ": relief by time of day</title>");
            out.emplace_back(tiles::kViewerPageFile, std::move(text));
        } else {
            out.emplace_back(f.name, std::move(text));
        }
    }
    return out;
}

}  // namespace ts::app
