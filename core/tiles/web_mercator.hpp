#pragma once
// Web Mercator (EPSG:3857) tile math: the XYZ scheme (x east from the antimeridian, y south from
// the top at 85.05 deg N), its TMS row flip (MBTiles) and Bing quadkeys.
//
// Pixels of a tile set are one global grid per "pixel zoom": a 256-px tile at zoom z and a 512-px
// tile at zoom z-1 have the same pixel size, so both are cut from the grid of pixel zoom
// P = z + log2(tile_size / 256), which has 256 * 2^P pixels on a side. Every pixel centre is
// computed from (global pixel index, P) alone (pixel_centre_m), in exact binary fractions, so the
// same ground pixel gets bit-identical coordinates whichever tile it falls in: the basis of the
// seam guarantee (docs/tiles.md).
#include <cstdint>
#include <string>

#include <glm/vec2.hpp>

namespace ts::tiles {

// WGS84 semi-major axis: Web Mercator's sphere.
inline constexpr double kEarthRadiusM = 6378137.0;
// Half the world's width in metres (the x of the antimeridian).
inline constexpr double kOriginShiftM = 3.14159265358979323846 * kEarthRadiusM;
// The latitude where the square world ends (atan(sinh(pi)), degrees).
inline constexpr double kMaxLatitudeDeg = 85.05112877980659;
inline constexpr int kMaxZoom = 24;

struct TileId {
    int z = 0, x = 0, y = 0;  // XYZ: y = 0 at the top (north)
    friend bool operator==(const TileId&, const TileId&) = default;
};

// Bounds of a tile in EPSG:3857 metres.
struct MercatorBounds {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // west, south, east, north
};

// Tiles per side at zoom z (2^z).
inline std::int64_t tiles_per_side(int z) { return std::int64_t(1) << z; }

MercatorBounds tile_bounds(const TileId& t);
// The XYZ tile (at zoom z) holding a point in metres; clamped to the world.
TileId tile_at(double mx, double my, int z);

// XYZ row <-> TMS row (y counted from the bottom), as MBTiles stores them. Its own inverse.
inline std::int64_t tms_row(int z, std::int64_t y) { return tiles_per_side(z) - 1 - y; }
// Bing Maps quadkey ("" at zoom 0).
std::string quadkey(const TileId& t);
// Its inverse; throws std::invalid_argument on a character other than 0-3.
TileId from_quadkey(const std::string& key);

// WGS84 lon/lat degrees <-> EPSG:3857 metres (the spherical formulas EPSG:3857 defines).
// Latitudes are clamped to +-kMaxLatitudeDeg.
glm::dvec2 lonlat_to_mercator(glm::dvec2 lonlat);
glm::dvec2 mercator_to_lonlat(glm::dvec2 m);

// log2(tile_size / 256) for 256, 512 (and any power of two >= 256); -1 otherwise.
int tile_size_shift(int tile_size);

// The centre of global pixel `index` (a column counted east from the antimeridian, or a row
// counted south from the top) on the grid of pixel zoom P, in metres: x for a column, -y for a
// row (rows run south). (index + 0.5) / 2^(P+8) is exact in double, so this is a pure function
// of (index, P).
inline double pixel_centre_m(std::int64_t index, int pixel_zoom) {
    const double fraction = (double(index) + 0.5) / double(std::int64_t(256) << pixel_zoom);
    return (2.0 * fraction - 1.0) * kOriginShiftM;
}
// Pixel size in metres at pixel zoom P.
inline double pixel_size_m(int pixel_zoom) {
    return 2.0 * kOriginShiftM / double(std::int64_t(256) << pixel_zoom);
}

}  // namespace ts::tiles
