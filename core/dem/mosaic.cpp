#include "core/dem/mosaic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/dem/decode_limits.hpp"
#include "core/util/error.hpp"

namespace ts::dem {

namespace {

// Cell sizes agree to 1e-9 relative (float rounding in the files' tags); offsets must be
// whole cells to 1e-3 of a cell, else the grids interleave and a mosaic would resample.
constexpr double kResolutionTolerance = 1e-9;
constexpr double kAlignmentTolerance = 1e-3;

bool close(double a, double b) { return std::abs(a - b) <= kResolutionTolerance * std::max(std::abs(a), std::abs(b)); }

}  // namespace

Dem mosaic(std::vector<Dem> parts) {
    if (parts.empty()) throw InputError("no DEM given");
    if (parts.size() == 1) return std::move(parts.front());

    const Dem& first = parts.front();
    const geo::GeoTransform& t0 = first.georef.transform();
    if (t0.dx_row != 0 || t0.dy_col != 0) throw input_error(first.source, "a rotated grid cannot be mosaicked");
    // Offsets of each part in cells of the first.
    std::vector<std::pair<long, long>> offsets;
    long min_c = 0, min_r = 0, max_c = 0, max_r = 0;
    for (const Dem& d : parts) {
        const geo::GeoTransform& t = d.georef.transform();
        if (!d.georef.crs().same_as(first.georef.crs()))
            throw input_error(d.source, "CRS " + d.georef.crs().name() + " differs from " + first.source + " (" +
                                            first.georef.crs().name() + "); reproject before mosaicking");
        if (t.dx_row != 0 || t.dy_col != 0) throw input_error(d.source, "a rotated grid cannot be mosaicked");
        if (!close(t.dx_col, t0.dx_col) || !close(t.dy_row, t0.dy_row))
            throw input_error(d.source, "cell size differs from " + first.source + "; resample before mosaicking");
        const double fc = (t.x0 - t0.x0) / t0.dx_col;
        const double fr = (t.y0 - t0.y0) / t0.dy_row;
        const long c = std::lround(fc), r = std::lround(fr);
        if (std::abs(fc - double(c)) > kAlignmentTolerance || std::abs(fr - double(r)) > kAlignmentTolerance)
            throw input_error(d.source, "grid is not aligned with " + first.source + " (offset by a fraction of a cell)");
        offsets.emplace_back(c, r);
        min_c = std::min(min_c, c);
        min_r = std::min(min_r, r);
        max_c = std::max(max_c, c + d.width);
        max_r = std::max(max_r, r + d.height);
    }
    const long width = max_c - min_c, height = max_r - min_r;
    if (width * height > (long(1) << 31)) throw input_error(first.source, "mosaic too large");
    // Tiles far apart on one grid span a large, mostly empty box.
    require_memory_for(first.source, "a mosaic of", std::uint64_t(width), std::uint64_t(height));

    Dem out;
    out.width = int(width);
    out.height = int(height);
    out.z.assign(std::size_t(width * height), std::numeric_limits<float>::quiet_NaN());
    out.void_mask.assign(out.z.size(), 1);
    out.vertical_datum = first.vertical_datum;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const Dem& d = parts[k];
        if (d.vertical_datum != out.vertical_datum) out.vertical_datum = "mixed";
        out.source += (k ? " + " : "") + d.source;
        const long c0 = offsets[k].first - min_c, r0 = offsets[k].second - min_r;
        for (int r = 0; r < d.height; ++r)
            for (int c = 0; c < d.width; ++c) {
                const std::size_t dst = out.index(int(c0 + c), int(r0 + r));
                const std::size_t src = d.index(c, r);
                // A shared edge cell keeps the first valid height; a void never hides a height.
                if (!d.void_mask[src] && out.void_mask[dst]) {
                    out.z[dst] = d.z[src];
                    out.void_mask[dst] = 0;
                }
            }
    }
    geo::GeoTransform t = t0;
    const glm::dvec2 origin = t0.apply(double(min_c), double(min_r));
    t.x0 = origin.x;
    t.y0 = origin.y;
    out.georef = geo::Georef(out.width, out.height, t, first.georef.crs_ptr(), first.georef.pixel_is_area());
    return out;
}

}  // namespace ts::dem
