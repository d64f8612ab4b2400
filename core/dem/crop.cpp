#include "core/dem/crop.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"

namespace ts::dem {

Dem crop(const Dem& dem, const LonLatBox& box) {
    std::ostringstream text;
    text << box.west << "," << box.south << "," << box.east << "," << box.north;
    if (!(box.west < box.east) || !(box.south < box.north) || box.south < -90 || box.north > 90)
        throw QuantityError(Quantity::crop, text.str(), "need W,S,E,N with W < E, S < N, latitudes within +-90");

    // Walk the box outline (32 steps a side) in pixel space: projected grids bend its edges.
    constexpr int kSteps = 32;
    double c_min = std::numeric_limits<double>::infinity(), r_min = c_min;
    double c_max = -c_min, r_max = -c_min;
    for (int i = 0; i <= kSteps; ++i) {
        const double f = double(i) / kSteps;
        const double lon = box.west + f * (box.east - box.west);
        const double lat = box.south + f * (box.north - box.south);
        for (glm::dvec2 ll : {glm::dvec2{lon, box.south}, glm::dvec2{lon, box.north}, glm::dvec2{box.west, lat},
                              glm::dvec2{box.east, lat}}) {
            const glm::dvec2 p = dem.georef.lonlat_to_pixel(ll);
            if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
            c_min = std::min(c_min, p.x);
            c_max = std::max(c_max, p.x);
            r_min = std::min(r_min, p.y);
            r_max = std::max(r_max, p.y);
        }
    }
    // Cells overlapping [c_min, c_max] x [r_min, r_max]; a 1e-9 slack keeps a box exactly on
    // cell edges from taking the neighbouring cell.
    const int col0 = std::max(0, int(std::floor(c_min + 1e-9)));
    const int row0 = std::max(0, int(std::floor(r_min + 1e-9)));
    const int col1 = std::min(dem.width, int(std::ceil(c_max - 1e-9)));
    const int row1 = std::min(dem.height, int(std::ceil(r_max - 1e-9)));
    if (!(c_min <= c_max) || col1 <= col0 || row1 <= row0)
        throw input_error(dem.source, "crop box " + text.str() + " does not overlap the DEM");

    Dem out;
    out.width = col1 - col0;
    out.height = row1 - row0;
    out.z.resize(std::size_t(out.width) * std::size_t(out.height));
    out.void_mask.resize(out.z.size());
    for (int r = 0; r < out.height; ++r)
        for (int c = 0; c < out.width; ++c) {
            out.z[out.index(c, r)] = dem.at(col0 + c, row0 + r);
            out.void_mask[out.index(c, r)] = dem.void_mask[dem.index(col0 + c, row0 + r)];
        }
    out.georef = dem.georef.window(col0, row0, out.width, out.height);
    out.vertical_datum = dem.vertical_datum;
    out.height_unit = dem.height_unit;
    out.credit = dem.credit;
    out.source = dem.source;
    return out;
}

Dem texel_window(const Dem& dem, int col0, int row0, int width, int height) {
    col0 = std::clamp(col0, 0, dem.width - 1);
    row0 = std::clamp(row0, 0, dem.height - 1);
    Dem out;
    out.width = std::clamp(width, 1, dem.width - col0);
    out.height = std::clamp(height, 1, dem.height - row0);
    out.z.resize(std::size_t(out.width) * std::size_t(out.height));
    out.void_mask.resize(out.z.size());
    for (int r = 0; r < out.height; ++r)
        for (int c = 0; c < out.width; ++c) {
            out.z[out.index(c, r)] = dem.at(col0 + c, row0 + r);
            out.void_mask[out.index(c, r)] = dem.void_mask.empty() ? 0 : dem.void_mask[dem.index(col0 + c, row0 + r)];
        }
    out.georef = dem.georef.window(col0, row0, out.width, out.height);
    out.vertical_datum = dem.vertical_datum;
    out.height_unit = dem.height_unit;
    out.credit = dem.credit;
    out.source = dem.source;
    return out;
}

}  // namespace ts::dem
