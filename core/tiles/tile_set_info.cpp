#include "core/tiles/tile_set_info.hpp"

#include <cstdio>

namespace ts::tiles {

namespace {

std::string fixed7(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.7f", v);
    return text;
}

double centre_lon(const TileSetInfo& i) { return 0.5 * (i.bounds.west + i.bounds.east); }
double centre_lat(const TileSetInfo& i) { return 0.5 * (i.bounds.south + i.bounds.north); }
int centre_zoom(const TileSetInfo& i) { return (i.minzoom + i.maxzoom) / 2; }

}  // namespace

std::string json_string(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') out += '\\', out += c;
        else if (c == '\n') out += "\\n";
        else if (c == '\t') out += "\\t";
        else if (u < 0x20) {
            char esc[8];
            std::snprintf(esc, sizeof esc, "\\u%04x", u);
            out += esc;
        } else if (c == '<') out += "\\u003c";  // never "</script>" when embedded in a page
        else out += c;
    }
    return out + "\"";
}

std::string html_text(const std::string& text) {
    std::string out;
    for (const char c : text) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else if (c == '\'') out += "&#39;";
        else out += c;
    }
    return out;
}

std::map<std::string, std::string> mbtiles_metadata(const TileSetInfo& i) {
    const LonLatBox& b = i.bounds;
    return {
        {"name", i.name},
        {"format", "png"},
        {"bounds", fixed7(b.west) + "," + fixed7(b.south) + "," + fixed7(b.east) + "," + fixed7(b.north)},
        {"center", fixed7(centre_lon(i)) + "," + fixed7(centre_lat(i)) + "," + std::to_string(centre_zoom(i))},
        {"minzoom", std::to_string(i.minzoom)},
        {"maxzoom", std::to_string(i.maxzoom)},
        {"attribution", i.attribution},
        {"type", "baselayer"},
        {"version", "1"},
        {"description", i.description},
    };
}

std::string tilejson_text(const TileSetInfo& i) {
    const LonLatBox& b = i.bounds;
    std::string j = "{\n";
    j += "  \"tilejson\": \"3.0.0\",\n";
    j += "  \"name\": " + json_string(i.name) + ",\n";
    j += "  \"description\": " + json_string(i.description) + ",\n";
    j += "  \"attribution\": " + json_string(i.attribution) + ",\n";
    j += "  \"version\": \"1.0.0\",\n";
    j += "  \"scheme\": \"xyz\",\n";
    j += "  \"tiles\": [\"{z}/{x}/{y}.png\"],\n";
    j += "  \"minzoom\": " + std::to_string(i.minzoom) + ",\n";
    j += "  \"maxzoom\": " + std::to_string(i.maxzoom) + ",\n";
    j += "  \"bounds\": [" + fixed7(b.west) + ", " + fixed7(b.south) + ", " + fixed7(b.east) + ", " + fixed7(b.north) +
         "],\n";
    j += "  \"center\": [" + fixed7(centre_lon(i)) + ", " + fixed7(centre_lat(i)) + ", " +
         std::to_string(centre_zoom(i)) + "],\n";
    if (!i.legend_file.empty())
        j += "  \"legend\": " +
             json_string("<img src=\"" + html_text(i.legend_file) + "\" alt=\"" + html_text(i.legend_alt) + "\">") +
             ",\n";
    j += "  \"tile_size\": " + std::to_string(i.tile_size) + "\n";
    return j + "}\n";
}

}  // namespace ts::tiles
