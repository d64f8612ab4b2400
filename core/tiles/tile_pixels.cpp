#include "core/tiles/tile_pixels.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace ts::tiles {

TileFrame tile_frame(const TileId& t, int tile_size) {
    const int shift = tile_size_shift(tile_size);
    if (shift < 0) throw std::invalid_argument("tile size must be 256 * 2^k");
    TileFrame f;
    f.tile = t;
    f.size = tile_size;
    f.pixel_zoom = t.z + shift;
    f.col0 = std::int64_t(t.x) * tile_size;
    f.row0 = std::int64_t(t.y) * tile_size;
    return f;
}

TilePixelMap::TilePixelMap(const dem::Dem& dem) : dem_(dem) {
    const geo::GeoTransform& t = dem.georef.transform();
    const auto epsg = dem.georef.crs().epsg();
    separable_ = epsg && *epsg == 4326 && t.dx_row == 0 && t.dy_col == 0;
    for (std::uint8_t v : dem.void_mask) has_voids_ = has_voids_ || v;
}

void TilePixelMap::locate(const TileFrame& f, int halo, std::vector<glm::dvec2>& at) const {
    const int n = f.size + 2 * halo;
    at.resize(std::size_t(n) * std::size_t(n));
    const geo::Georef& g = dem_.georef;
    if (separable_) {
        // lon of a column and lat of a row, each once.
        std::vector<double> px(static_cast<std::size_t>(n)), py(static_cast<std::size_t>(n));
        const glm::dvec2 origin = mercator_to_lonlat({0.0, 0.0});
        for (int i = 0; i < n; ++i) {
            const double lon = mercator_to_lonlat({pixel_centre_m(f.col0 + i - halo, f.pixel_zoom), 0.0}).x;
            px[std::size_t(i)] = g.lonlat_to_pixel({lon, origin.y}).x;
            const double lat = mercator_to_lonlat({0.0, -pixel_centre_m(f.row0 + i - halo, f.pixel_zoom)}).y;
            py[std::size_t(i)] = g.lonlat_to_pixel({origin.x, lat}).y;
        }
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) at[std::size_t(j) * n + i] = {px[std::size_t(i)], py[std::size_t(j)]};
        return;
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int j = 0; j < n; ++j) {
        const double y = -pixel_centre_m(f.row0 + j - halo, f.pixel_zoom);
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 ll = mercator_to_lonlat({pixel_centre_m(f.col0 + i - halo, f.pixel_zoom), y});
            glm::dvec2 p = g.lonlat_to_pixel(ll);
            if (!std::isfinite(p.x) || !std::isfinite(p.y)) p = {nan, nan};
            at[std::size_t(j) * n + i] = p;
        }
    }
}

bool TilePixelMap::covered(glm::dvec2 p) const {
    // Edge coordinates: the DEM covers [0, width] x [0, height].
    if (!(p.x >= 0 && p.y >= 0 && p.x <= dem_.width && p.y <= dem_.height)) return false;
    if (!has_voids_) return true;
    const int c = std::min(int(p.x), dem_.width - 1), r = std::min(int(p.y), dem_.height - 1);
    return dem_.void_mask[std::size_t(r) * std::size_t(dem_.width) + std::size_t(c)] == 0;
}

}  // namespace ts::tiles
