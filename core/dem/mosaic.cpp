#include "core/dem/mosaic.hpp"

#include <algorithm>
#include <climits>
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

MosaicPlan plan_mosaic(const std::vector<DemLayout>& parts) {
    if (parts.empty()) throw InputError("no DEM given");
    if (parts.size() == 1) return {parts.front(), {{0, 0}}};

    const DemLayout& first = parts.front();
    const geo::GeoTransform& t0 = first.georef.transform();
    if (t0.dx_row != 0 || t0.dy_col != 0) throw input_error(first.source, "a rotated grid cannot be mosaicked");
    // Offsets of each part in cells of the first.
    std::vector<std::pair<long, long>> offsets;
    long min_c = 0, min_r = 0, max_c = 0, max_r = 0;
    for (const DemLayout& d : parts) {
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
    if (width > INT_MAX || height > INT_MAX) throw input_error(first.source, "mosaic too large");

    MosaicPlan plan;
    DemLayout& out = plan.layout;
    out.width = int(width);
    out.height = int(height);
    out.vertical_datum = first.vertical_datum;
    out.height_unit = first.height_unit;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        if (parts[k].vertical_datum != out.vertical_datum) out.vertical_datum = "mixed";
        if (parts[k].height_unit != out.height_unit) out.height_unit = "mixed (each converted to metres)";
        // Each source credited once.
        if (!parts[k].credit.empty() && out.credit.find(parts[k].credit) == std::string::npos)
            out.credit += (out.credit.empty() ? "" : "; ") + parts[k].credit;
        out.source += (k ? " + " : "") + parts[k].source;
        plan.offsets.emplace_back(int(offsets[k].first - min_c), int(offsets[k].second - min_r));
    }
    geo::GeoTransform t = t0;
    const glm::dvec2 origin = t0.apply(double(min_c), double(min_r));
    t.x0 = origin.x;
    t.y0 = origin.y;
    out.georef = geo::Georef(out.width, out.height, t, first.georef.crs_ptr(), first.georef.pixel_is_area());
    return plan;
}

void merge_into(const float* z, const std::uint8_t* voids, float* out_z, std::uint8_t* out_voids, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
        if (!voids[i] && out_voids[i]) {
            out_z[i] = z[i];
            out_voids[i] = 0;
        }
}

Dem mosaic(std::vector<Dem> parts) {
    if (parts.empty()) throw InputError("no DEM given");
    if (parts.size() == 1) return std::move(parts.front());

    std::vector<DemLayout> layouts;
    layouts.reserve(parts.size());
    for (const Dem& d : parts) layouts.push_back(layout_of(d));
    const MosaicPlan plan = plan_mosaic(layouts);
    const std::string& first = parts.front().source;
    const std::uint64_t width = std::uint64_t(plan.layout.width), height = std::uint64_t(plan.layout.height);
    if (width * height > kMaxDemCells) throw input_error(first, "mosaic too large");
    // Tiles far apart on one grid span a large, mostly empty box.
    require_memory_for(first, "a mosaic of", width, height);

    Dem out = allocate_dem(plan.layout);
    std::fill(out.z.begin(), out.z.end(), std::numeric_limits<float>::quiet_NaN());
    std::fill(out.void_mask.begin(), out.void_mask.end(), std::uint8_t(1));
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const Dem& d = parts[k];
        const auto [c0, r0] = plan.offsets[k];
        for (int r = 0; r < d.height; ++r) {
            const std::size_t src = d.index(0, r), dst = out.index(c0, r0 + r);
            merge_into(&d.z[src], &d.void_mask[src], &out.z[dst], &out.void_mask[dst], std::size_t(d.width));
        }
    }
    return out;
}

}  // namespace ts::dem
