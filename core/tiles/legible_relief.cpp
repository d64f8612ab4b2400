#include "core/tiles/legible_relief.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/material/palette_materials.hpp"
#include "core/terrain/dem_height_grid.hpp"
#include "core/util/angles.hpp"

namespace ts::tiles {
namespace {

constexpr int kSamplesPerSide = 128;

// The mean of the finite heights of level texel (c, r): the DEM's block of 2^level a side (what
// dem_level's texel holds where the block has no void); NaN if all of it is void.
double level_height(const dem::Dem& dem, int level, int c, int r) {
    const int n = 1 << level;
    double sum = 0;
    int count = 0;
    for (int y = r * n; y < std::min(dem.height, (r + 1) * n); ++y)
        for (int x = c * n; x < std::min(dem.width, (c + 1) * n); ++x) {
            const float h = dem.at(x, y);
            if (std::isfinite(h)) sum += h, ++count;
        }
    return count ? sum / count : std::nan("");
}

// Indices 1..size-2 spread evenly, at most kSamplesPerSide of them.
std::vector<int> spread(int size) {
    std::vector<int> out;
    const int inner = size - 2;
    if (inner <= 0) return out;
    const int n = std::min(inner, kSamplesPerSide);
    for (int k = 0; k < n; ++k) out.push_back(1 + int((k + 0.5) * inner / n));
    return out;
}

}  // namespace

double steep_slope(const dem::Dem& dem, int level) {
    const int w = dem.width >> level, h = dem.height >> level;
    const terrain::HeightGrid metric = terrain::metric_view(dem);
    bool sea_floor = false;  // as render::fit_colors decides it
    for (const float z : dem.z)
        if (z < render::kSeaFloorBelowM) {
            sea_floor = true;
            break;
        }
    const double scale = double(1 << level);
    std::vector<double> tans;
    for (const int r : spread(h)) {
        const std::size_t dem_row = std::min(std::size_t(dem.height - 1), std::size_t((r + 0.5) * scale));
        const double dx = metric.dx_m[dem_row] * scale, dy = metric.dy_m[dem_row] * scale;
        if (!(dx > 0) || !(dy > 0)) continue;
        const int step = std::max(1, int(std::lround(dy / dx)));  // east-west over a square
        for (const int c : spread(w)) {
            if (c - step < 0 || c + step >= w) continue;
            const double centre = level_height(dem, level, c, r);
            if (!std::isfinite(centre) || (sea_floor && !(centre > 0))) continue;
            const double gx =
                (level_height(dem, level, c + step, r) - level_height(dem, level, c - step, r)) / (2 * step * dx);
            const double gy = (level_height(dem, level, c, r + 1) - level_height(dem, level, c, r - 1)) / (2 * dy);
            if (std::isfinite(gx) && std::isfinite(gy)) tans.push_back(std::hypot(gx, gy));
        }
    }
    if (tans.size() < 16) return 0;
    const auto at = tans.begin() + std::ptrdiff_t(kLegibleSlopePercentile * double(tans.size() - 1));
    std::nth_element(tans.begin(), at, tans.end());
    return *at;
}

double legible_exaggeration(double zoom_e, double steep_tan) {
    if (!(zoom_e > 1) || !(steep_tan > 0)) return zoom_e;
    const double wanted = std::tan(radians(kLegibleSlopeDeg)) / steep_tan;
    return std::clamp(wanted, zoom_e, std::min(4 * zoom_e, zoom_e * zoom_e));
}

}  // namespace ts::tiles
