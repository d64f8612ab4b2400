// SRTM .hgt tiles: a square of big-endian int16 heights (EGM96 geoid, metres), row 0 north,
// void = -32768. The file name (N00E010.hgt) names the south-west cell *centre*: cell centres
// sit on whole degrees, so the raster's outer edges lie half a cell outside them.
#include <cmath>
#include <fstream>
#include <limits>
#include <regex>

#include <zip.h>

#include "core/dem/decode_limits.hpp"
#include "core/dem/read_dem.hpp"
#include "core/util/error.hpp"

namespace ts::dem {

namespace {

constexpr std::int16_t kHgtVoid = -32768;

// Side of the tile from its byte count: 1201 (SRTM3) or 3601 (SRTM1); 0 if neither.
int hgt_side(std::size_t bytes) {
    for (int side : {1201, 3601})
        if (bytes == std::size_t(side) * std::size_t(side) * 2) return side;
    return 0;
}

// "N00E010" anywhere in the name -> {lon, lat} of the south-west cell centre.
bool parse_hgt_corner(const std::string& name, int& lon, int& lat) {
    static const std::regex pattern(R"(([NS])(\d{1,2})([EW])(\d{1,3}))", std::regex::icase);
    std::smatch m;
    if (!std::regex_search(name, m, pattern)) return false;
    lat = std::stoi(m[2]) * (std::toupper(m[1].str()[0]) == 'S' ? -1 : 1);
    lon = std::stoi(m[4]) * (std::toupper(m[3].str()[0]) == 'W' ? -1 : 1);
    return lat >= -90 && lat < 90 && lon >= -180 && lon < 180;
}

// The error for a byte count that is no tile, from the size alone: callers check it before
// they read (or inflate) anything.
void require_hgt_size(std::uint64_t bytes, const std::string& source) {
    if (bytes == 0) throw input_error(source, "empty file");
    if (bytes <= std::numeric_limits<std::size_t>::max() && hgt_side(std::size_t(bytes)) != 0) return;
    throw input_error(source, "not an SRTM .hgt tile: " + std::to_string(bytes) +
                                  " bytes, expected 2884802 (1201x1201) or 25934402 (3601x3601); truncated?");
}

}  // namespace

Dem read_hgt_bytes(const std::string& bytes, const std::string& name, const std::string& source) {
    require_hgt_size(bytes.size(), source);
    const int side = hgt_side(bytes.size());
    require_memory_for(source, "decoding", std::uint64_t(side), std::uint64_t(side));
    int lon = 0, lat = 0;
    if (!parse_hgt_corner(std::filesystem::path(name).filename().string(), lon, lat))
        throw input_error(source, "an .hgt file name must give its south-west corner, like N45E006.hgt");

    Dem dem;
    dem.width = dem.height = side;
    dem.z.resize(std::size_t(side) * side);
    dem.void_mask.assign(dem.z.size(), 0);
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
    for (std::size_t i = 0; i < dem.z.size(); ++i) {
        const auto v = static_cast<std::int16_t>(std::uint16_t(p[2 * i] << 8 | p[2 * i + 1]));
        if (v == kHgtVoid) {
            dem.z[i] = std::numeric_limits<float>::quiet_NaN();
            dem.void_mask[i] = 1;
        } else {
            dem.z[i] = float(v);
        }
    }
    const double cell = 1.0 / (side - 1);
    geo::GeoTransform t;
    t.x0 = lon - 0.5 * cell;
    t.dx_col = cell;
    t.y0 = lat + 1 + 0.5 * cell;
    t.dy_row = -cell;
    dem.georef = geo::Georef(side, side, t, geo::Crs::wgs84(), /*pixel_is_area=*/false);
    dem.vertical_datum = "EGM96 geoid";
    dem.source = source;
    return dem;
}

Dem read_hgt(const std::filesystem::path& path) {
    const std::string source = path.string();
    std::error_code ec;
    const std::uint64_t size = std::filesystem::file_size(path, ec);
    if (ec) throw input_error(source, "cannot read (" + ec.message() + ")");
    require_hgt_size(size, source);  // a mislabelled multi-gigabyte file is not read first
    std::ifstream in(path, std::ios::binary);
    if (!in) throw input_error(source, "cannot open");
    std::string bytes(std::size_t(size), '\0');
    in.read(bytes.data(), std::streamsize(bytes.size()));
    bytes.resize(std::size_t(in.gcount()));  // shrank while read: read_hgt_bytes says so
    return read_hgt_bytes(bytes, path.filename().string(), source);
}

Dem read_hgt_zip(const std::filesystem::path& path) {
    const std::string source = path.string();
    int err = 0;
    zip_t* archive = zip_open(source.c_str(), ZIP_RDONLY, &err);
    if (!archive) throw input_error(source, "not a readable zip archive");
    struct Closer {
        zip_t* z;
        ~Closer() { zip_discard(z); }
    } closer{archive};

    const zip_int64_t n = zip_get_num_entries(archive, 0);
    for (zip_int64_t i = 0; i < n; ++i) {
        zip_stat_t st;
        if (zip_stat_index(archive, zip_uint64_t(i), 0, &st) != 0 || !(st.valid & ZIP_STAT_NAME)) continue;
        std::string entry = st.name;
        std::string lower = entry;
        for (auto& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
        if (lower.size() < 4 || lower.compare(lower.size() - 4, 4, ".hgt") != 0) continue;
        const std::string where = source + " (" + entry + ")";
        if (!(st.valid & ZIP_STAT_SIZE)) throw input_error(where, "zip entry without a size");
        require_hgt_size(st.size, where);  // before anything is inflated
        zip_file_t* f = zip_fopen_index(archive, zip_uint64_t(i), 0);
        if (!f) throw input_error(where, "cannot read the zip entry");
        std::string bytes(st.size, '\0');
        const zip_int64_t got = zip_fread(f, bytes.data(), st.size);
        zip_fclose(f);
        if (got < 0) throw input_error(where, "corrupt zip entry");
        bytes.resize(std::size_t(got));
        // The corner comes from the entry's name, else from the archive's (N00E011.hgt.zip).
        const std::string names = std::filesystem::path(entry).filename().string() + "|" + path.filename().string();
        Dem dem = read_hgt_bytes(bytes, names, where);
        dem.source = source;
        return dem;
    }
    throw input_error(source, "zip archive holds no .hgt file");
}

}  // namespace ts::dem
