#include "core/tiles/lightable_page.hpp"

#include <stdexcept>

#include "core/tiles/tile_viewer.hpp"

namespace ts::tiles {

std::vector<std::pair<std::string, std::string>> lightable_viewer_files(const TileSetInfo& info) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const EmbeddedFile& f : lightable_page_files()) {
        std::string text(f.text);
        if (std::string_view(f.name) == "map.html") {
            const std::string module = "<script type=\"module\" src=\"map.mjs\"></script>";
            const auto at = text.find(module);
            if (at == std::string::npos) throw std::logic_error("web/lightable/map.html: no map.mjs script");
            text.insert(at, std::string("<script>window.TERRASHADE_MAPLIBRE = {js: '") + kMaplibreJsUrl +
                                "', jsIntegrity: '" + kMaplibreJsSri + "', css: '" + kMaplibreCssUrl +
                                "', cssIntegrity: '" + kMaplibreCssSri + "'};</script>\n");
            const std::string title = "<title>terrashade: relief by time of day</title>";
            if (const auto t = text.find(title); t != std::string::npos)
                text.replace(t, title.size(), "<title>" + html_text(info.name) + ": relief by time of day</title>");
            out.emplace_back(kViewerPageFile, std::move(text));
        } else {
            out.emplace_back(f.name, std::move(text));
        }
    }
    return out;
}

}  // namespace ts::tiles
