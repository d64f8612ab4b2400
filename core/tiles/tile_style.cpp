#include "core/tiles/tile_style.hpp"

#include <string>

#include "core/util/error.hpp"

namespace ts::tiles {

TileStyle parse_tile_style(std::string_view text) {
    for (TileStyle s : {TileStyle::relief, TileStyle::hillshade, TileStyle::multidirectional, TileStyle::svf,
                        TileStyle::color})
        if (text == tile_style_name(s)) return s;
    throw InputError("--style " + std::string(text) + ": use relief, hillshade, multidirectional, svf or color");
}

std::string_view tile_style_name(TileStyle s) {
    switch (s) {
        case TileStyle::relief: return "relief";
        case TileStyle::hillshade: return "hillshade";
        case TileStyle::multidirectional: return "multidirectional";
        case TileStyle::svf: return "svf";
        case TileStyle::color: return "color";
    }
    return "?";
}

}  // namespace ts::tiles
