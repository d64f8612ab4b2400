#include "core/tiles/dem_footprint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ts::tiles {
namespace {

// A DEM around a pole (a polar stereographic grid) has an outline that never reaches it: the
// box then runs up to Web Mercator's edge, all the way round. `has_terrain(col, row)`: whether
// the texel holding the pole is terrain.
template <class HasTerrain>
void include_poles(const geo::Georef& g, double& west, double& south, double& east, double& north,
                   HasTerrain has_terrain) {
    for (const double lat : {90.0, -90.0}) {
        const glm::dvec2 px = g.lonlat_to_pixel({0.0, lat});
        if (!(std::isfinite(px.x) && std::isfinite(px.y) && px.x >= 0 && px.y >= 0 && px.x <= g.width() &&
              px.y <= g.height()))
            continue;
        if (!has_terrain(std::min(int(px.x), g.width() - 1), std::min(int(px.y), g.height() - 1))) continue;
        west = -180.0, east = 180.0;
        (lat > 0 ? north : south) = lat;
    }
}

}  // namespace

LonLatBox dem_footprint(const geo::Georef& g) {
    constexpr int kPerEdge = 64;
    double w = std::numeric_limits<double>::infinity(), e = -w, s = w, n = -w;
    auto add = [&](double col, double row) {
        const glm::dvec2 ll = g.pixel_to_lonlat(col, row);
        if (!std::isfinite(ll.x) || !std::isfinite(ll.y)) return;
        w = std::min(w, ll.x), e = std::max(e, ll.x), s = std::min(s, ll.y), n = std::max(n, ll.y);
    };
    for (int i = 0; i <= kPerEdge; ++i) {
        const double f = double(i) / kPerEdge;
        add(f * g.width(), 0), add(f * g.width(), g.height());
        add(0, f * g.height()), add(g.width(), f * g.height());
    }
    if (!g.crs().is_geographic()) include_poles(g, w, s, e, n, [](int, int) { return true; });
    LonLatBox box{std::max(w, -180.0), std::max(s, -kMaxLatitudeDeg), std::min(e, 180.0),
                  std::min(n, kMaxLatitudeDeg)};
    if (box.empty()) return {};
    return box;
}

LonLatBox terrain_footprint(const dem::Dem& dem) {
    const int w = dem.width, h = dem.height;
    if (std::none_of(dem.z.begin(), dem.z.end(), [](float v) { return std::isnan(v); })) return dem_footprint(dem.georef);
    // Per row and per column, the first and last texel with a height (-1: none).
    std::vector<int> row_first(std::size_t(h), -1), row_last(std::size_t(h), -1);
    std::vector<int> col_first(std::size_t(w), -1), col_last(std::size_t(w), -1);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            if (std::isnan(dem.z[dem.index(c, r)])) continue;
            if (row_first[std::size_t(r)] < 0) row_first[std::size_t(r)] = c;
            row_last[std::size_t(r)] = c;
            if (col_first[std::size_t(c)] < 0) col_first[std::size_t(c)] = r;
            col_last[std::size_t(c)] = r;
        }
    double west = std::numeric_limits<double>::infinity(), east = -west, south = west, north = -west;
    auto add_texel = [&](int c, int r) {  // its four corners
        for (auto [dc, dr] : {std::pair{0, 0}, {1, 0}, {0, 1}, {1, 1}}) {
            const glm::dvec2 ll = dem.georef.pixel_to_lonlat(c + dc, r + dr);
            if (!std::isfinite(ll.x) || !std::isfinite(ll.y)) continue;
            west = std::min(west, ll.x), east = std::max(east, ll.x);
            south = std::min(south, ll.y), north = std::max(north, ll.y);
        }
    };
    for (int r = 0; r < h; ++r)
        if (row_first[std::size_t(r)] >= 0) add_texel(row_first[std::size_t(r)], r), add_texel(row_last[std::size_t(r)], r);
    for (int c = 0; c < w; ++c)
        if (col_first[std::size_t(c)] >= 0) add_texel(c, col_first[std::size_t(c)]), add_texel(c, col_last[std::size_t(c)]);
    if (!dem.georef.crs().is_geographic())
        include_poles(dem.georef, west, south, east, north,
                      [&](int c, int r) { return !std::isnan(dem.z[dem.index(c, r)]); });
    LonLatBox box{std::max(west, -180.0), std::max(south, -kMaxLatitudeDeg), std::min(east, 180.0),
                  std::min(north, kMaxLatitudeDeg)};
    if (box.empty()) return {};
    return box;
}

std::vector<TileId> tiles_covering(const LonLatBox& box, int z0, int z1) {
    std::vector<TileId> out;
    if (box.empty()) return out;
    const glm::dvec2 sw = lonlat_to_mercator({box.west, box.south});
    const glm::dvec2 ne = lonlat_to_mercator({box.east, box.north});
    for (int z = z0; z <= z1; ++z) {
        const double size = 2.0 * kOriginShiftM / double(tiles_per_side(z));
        const std::int64_t last = tiles_per_side(z) - 1;
        // Half-open: a box edge exactly on a tile border does not pull in the next tile.
        auto first_index = [&](double v) { return std::clamp<std::int64_t>(std::int64_t(std::floor(v / size)), 0, last); };
        auto last_index = [&](double v) { return std::clamp<std::int64_t>(std::int64_t(std::ceil(v / size)) - 1, 0, last); };
        const std::int64_t x0 = first_index(sw.x + kOriginShiftM), x1 = last_index(ne.x + kOriginShiftM);
        const std::int64_t y0 = first_index(kOriginShiftM - ne.y), y1 = last_index(kOriginShiftM - sw.y);
        for (std::int64_t y = y0; y <= y1; ++y)
            for (std::int64_t x = x0; x <= x1; ++x) out.push_back({z, int(x), int(y)});
    }
    return out;
}

}  // namespace ts::tiles
