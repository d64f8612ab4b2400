#include "core/dem/wrap_longitude.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ts::dem {

bool spans_all_longitudes(const Dem& dem) {
    if (!dem.georef.valid() || !dem.georef.crs().is_geographic() || dem.width < 2) return false;
    const geo::GeoTransform& t = dem.georef.transform();
    if (t.dx_row != 0 || t.dy_col != 0 || !(t.dx_col > 0)) return false;
    return dem.width * t.dx_col >= 360.0 - 0.5 * t.dx_col;
}

Dem wrap_longitudes(const Dem& dem, int columns) {
    if (columns <= 0 || !spans_all_longitudes(dem)) return dem;
    const geo::GeoTransform& t = dem.georef.transform();
    // Columns a whole turn apart: 360 for a 1-degree grid (ETOPO1's 361 repeat 180 at both ends).
    const int period = int(std::lround(360.0 / t.dx_col));
    Dem out = dem;
    out.width = dem.width + 2 * columns;
    out.z.assign(std::size_t(out.width) * std::size_t(out.height), 0.0f);
    out.void_mask.assign(out.z.size(), 0);
    // Each column's source, once.
    std::vector<int> source(std::size_t(out.width));
    for (int c = 0; c < out.width; ++c) {
        int src = c - columns;
        while (src < 0) src += period;
        while (src >= dem.width) src -= period;
        source[std::size_t(c)] = std::max(src, 0);  // a grid a cell short of the turn: its first column stands in
    }
    for (int r = 0; r < dem.height; ++r)
        for (int c = 0; c < out.width; ++c) {
            const std::size_t from = dem.index(source[std::size_t(c)], r);
            out.z[out.index(c, r)] = dem.z[from];
            if (!dem.void_mask.empty()) out.void_mask[out.index(c, r)] = dem.void_mask[from];
        }
    geo::GeoTransform w = t;
    w.x0 = t.x0 - columns * t.dx_col;
    out.georef = geo::Georef(out.width, out.height, w, dem.georef.crs_ptr(), dem.georef.pixel_is_area());
    return out;
}

}  // namespace ts::dem
