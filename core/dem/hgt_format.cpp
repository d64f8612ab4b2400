#include "core/dem/hgt_format.hpp"

#include <cctype>
#include <filesystem>
#include <limits>
#include <regex>

#include "core/util/error.hpp"

namespace ts::dem {

namespace {

constexpr std::int16_t kHgtVoid = -32768;

// "N00E010" anywhere in the name -> {lon, lat} of the south-west cell centre.
bool parse_hgt_corner(const std::string& name, int& lon, int& lat) {
    static const std::regex pattern(R"(([NS])(\d{1,2})([EW])(\d{1,3}))", std::regex::icase);
    std::smatch m;
    if (!std::regex_search(name, m, pattern)) return false;
    lat = std::stoi(m[2]) * (std::toupper(m[1].str()[0]) == 'S' ? -1 : 1);
    lon = std::stoi(m[4]) * (std::toupper(m[3].str()[0]) == 'W' ? -1 : 1);
    return lat >= -90 && lat < 90 && lon >= -180 && lon < 180;
}

}  // namespace

int hgt_side(std::uint64_t bytes) {
    for (int side : {1201, 3601})
        if (bytes == std::uint64_t(side) * std::uint64_t(side) * 2) return side;
    return 0;
}

void require_hgt_size(std::uint64_t bytes, const std::string& source) {
    if (bytes == 0) throw input_error(source, "empty file");
    if (hgt_side(bytes) != 0) return;
    throw input_error(source, "not an SRTM .hgt tile: " + std::to_string(bytes) +
                                  " bytes, expected 2884802 (1201x1201) or 25934402 (3601x3601); truncated?");
}

DemLayout hgt_layout(int side, const std::string& name, const std::string& source) {
    int lon = 0, lat = 0;
    if (!parse_hgt_corner(std::filesystem::path(name).filename().string(), lon, lat))
        throw input_error(source, "an .hgt file name must give its south-west corner, like N45E006.hgt");
    const double cell = 1.0 / (side - 1);
    geo::GeoTransform t;
    t.x0 = lon - 0.5 * cell;
    t.dx_col = cell;
    t.y0 = lat + 1 + 0.5 * cell;
    t.dy_row = -cell;
    DemLayout layout;
    layout.width = layout.height = side;
    layout.georef = geo::Georef(side, side, t, geo::Crs::wgs84(), /*pixel_is_area=*/false);
    layout.vertical_datum = "EGM96 geoid";
    layout.credit = "SRTM (NASA, NGA)";
    layout.source = source;
    return layout;
}

void decode_hgt_heights(const unsigned char* p, std::size_t n, float* z, std::uint8_t* voids) {
    for (std::size_t i = 0; i < n; ++i) {
        const auto v = static_cast<std::int16_t>(std::uint16_t(p[2 * i] << 8 | p[2 * i + 1]));
        const bool is_void = v == kHgtVoid;
        z[i] = is_void ? std::numeric_limits<float>::quiet_NaN() : float(v);
        voids[i] = is_void ? 1 : 0;
    }
}

}  // namespace ts::dem
