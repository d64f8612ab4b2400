#include "core/tiles/dem_level.hpp"

#include <cmath>

#include "core/terrain/height_pyramid.hpp"

namespace ts::tiles {

dem::Dem dem_level(const dem::Dem& dem, int level, int threads) {
    dem::Dem out;
    out.vertical_datum = dem.vertical_datum;
    out.credit = dem.credit;
    out.source = dem.source;
    out.width = dem.width, out.height = dem.height;
    out.z = dem.z;
    // Void share per texel (1 = all void), averaged with the heights.
    std::vector<float> voids(dem.z.size(), 0.0f);
    for (std::size_t k = 0; k < dem.void_mask.size(); ++k) voids[k] = dem.void_mask[k] ? 1.0f : 0.0f;
    for (int l = 0; l < level && (out.width > 1 || out.height > 1); ++l) {
        out.z = terrain::downsample_2x2(out.z.data(), out.width, out.height, false, threads);
        voids = terrain::downsample_2x2(voids.data(), out.width, out.height, false, threads);
        out.width = (out.width + 1) / 2, out.height = (out.height + 1) / 2;
    }
    out.void_mask.resize(voids.size());
    for (std::size_t k = 0; k < voids.size(); ++k) out.void_mask[k] = voids[k] >= 1.0f ? 1 : 0;
    geo::GeoTransform t = dem.georef.transform();
    // Texel (c, r) of the level starts at level-0 texel (c, r) * 2^L; an odd last column or row
    // reaches past the DEM's edge by less than a texel (tiles map through level-0 coordinates).
    const double s = double(1 << level);
    t.dx_col *= s, t.dy_col *= s, t.dx_row *= s, t.dy_row *= s;
    out.georef = geo::Georef(out.width, out.height, t, dem.georef.crs_ptr(), dem.georef.pixel_is_area());
    return out;
}

}  // namespace ts::tiles
