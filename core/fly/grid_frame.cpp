#include "core/fly/grid_frame.hpp"

#include <algorithm>
#include <cmath>

namespace ts::fly {
namespace {

// Linear interpolation of a per-row table at a fractional row, extrapolated with the end
// slopes beyond the grid (north) or clamped (spacing).
double interpolate(const std::vector<double>& v, double row, bool extrapolate) {
    const int n = int(v.size());
    if (n == 1) return v[0];
    const double r = extrapolate ? row : std::clamp(row, 0.0, double(n - 1));
    const int i = std::clamp(int(std::floor(r)), 0, n - 2);
    const double f = r - i;
    return v[std::size_t(i)] + f * (v[std::size_t(i + 1)] - v[std::size_t(i)]);
}

}  // namespace

GridFrame::GridFrame(const terrain::HeightGrid& grid)
    : width_(grid.width), height_(grid.height), centre_col_(0.5 * (grid.width - 1)) {
    dx_ = grid.dx_m;
    north_.assign(std::size_t(height_), 0.0);
    for (int r = 1; r < height_; ++r) {
        const double dy = 0.5 * (grid.dy_m[std::size_t(r - 1)] + grid.dy_m[std::size_t(r)]);
        north_[std::size_t(r)] = north_[std::size_t(r - 1)] - dy;
    }
    const double mid = interpolate(north_, 0.5 * (height_ - 1), false);
    for (double& n : north_) n -= mid;
}

double GridFrame::dx_at(double row) const { return interpolate(dx_, row, false); }
double GridFrame::north_at(double row) const { return interpolate(north_, row, true); }

glm::dvec2 GridFrame::to_metric(double col, double row) const {
    return {(col - centre_col_) * dx_at(row), north_at(row)};
}

glm::dvec2 GridFrame::to_grid(double east_m, double north_m) const {
    // north_ decreases with the row: bisection on the interpolated (monotone) function.
    double lo = -double(height_), hi = 2.0 * height_;
    for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (north_at(mid) > north_m) lo = mid;
        else hi = mid;
    }
    const double row = 0.5 * (lo + hi);
    return {east_m / dx_at(row) + centre_col_, row};
}

}  // namespace ts::fly
