#include "core/visibility/row_metrics.hpp"

#include <algorithm>
#include <cmath>

#include "core/util/error.hpp"

namespace ts::visibility {

RowMetrics::RowMetrics(const terrain::HeightGrid& grid) : dx_(grid.dx_m), dy_(grid.dy_m) {
    if (grid.width < 1 || grid.height < 1) throw InputError("height grid: empty");
    if (int(dx_.size()) != grid.height || int(dy_.size()) != grid.height)
        throw InputError("height grid: dx_m/dy_m must have one entry per row");
    for (std::size_t r = 0; r < dx_.size(); ++r) {
        if (!(dy_[r] > 0) || !(dx_[r] >= 0)) throw InputError("height grid: non-positive cell size");
        // A geographic grid's pole row has no east-west extent (and rows next to it almost
        // none); floor the width at 1% of the height so the constant-azimuth lines stay finite.
        dx_[r] = std::max(dx_[r], kMinAspect * dy_[r]);
    }
    g_.resize(dx_.size());
    g_[0] = 0;
    for (std::size_t r = 1; r < g_.size(); ++r) g_[r] = g_[r - 1] + 0.5 * (dy_[r - 1] / dx_[r - 1] + dy_[r] / dx_[r]);
    mean_rho_ = g_.size() > 1 ? g_.back() / double(g_.size() - 1) : dy_[0] / dx_[0];
    min_rho_ = dy_[0] / dx_[0];
    for (std::size_t r = 1; r < dx_.size(); ++r) min_rho_ = std::min(min_rho_, dy_[r] / dx_[r]);
}

double RowMetrics::row_of_g(double value) const {
    const int last = int(g_.size()) - 1;
    if (last == 0 || value <= 0) return 0.0;
    if (value >= g_.back()) return double(last);
    // rho varies slowly (cos(latitude)), so the guess is off by at most a row or two.
    return row_in_bracket(value, bracket(value, int(value / mean_rho_)));
}

}  // namespace ts::visibility
