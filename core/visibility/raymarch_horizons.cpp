// The reference: from each receiver texel centre, march the line of constant azimuth over the
// bilinear surface in steps of at most 0.25 texel out to the grid's edge, keeping the highest
// curvature-corrected elevation. The only shortcut is exact: stop once even the grid's highest
// point could not rise above the best angle found so far.
#include <algorithm>
#include <cmath>

#include "core/util/parallel_for.hpp"
#include "core/util/progress_bar.hpp"
#include "core/visibility/bilinear_march.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/receiver_setup.hpp"
#include "core/visibility/row_metrics.hpp"
#include "core/visibility/surface_sampling.hpp"

namespace ts::visibility {

HorizonSet raymarch_horizons(const terrain::HeightGrid& grid, const HorizonOptions& options) {
    const RowMetrics metrics(grid);
    const ReceiverWindow win = resolve_window(grid, options.window);
    HorizonSet out = zero_horizons(win, options.directions);
    const double curvature = curvature_factor(options.curvature);
    const float z_top = highest_height(grid);
    std::vector<double> cs(std::size_t(options.directions)), sn(cs.size());
    for (int d = 0; d < options.directions; ++d)
        cs[std::size_t(d)] = std::cos(azimuth_rad(d, options.directions)),
        sn[std::size_t(d)] = std::sin(azimuth_rad(d, options.directions));
    parallel_for(win.height, thread_count(options.threads), [&](int lr, int) {
        const int row = win.row0 + lr;
        for (int lc = 0; lc < win.width; ++lc) {
            const int col = win.col0 + lc;
            const float z0 = grid.at(col, row);
            if (std::isnan(z0)) continue;  // void receiver; the dispatcher writes NaN
            for (int d = 0; d < options.directions; ++d) {
                const double t = march_max_slope(grid, metrics, curvature, z_top, col, row, z0, cs[std::size_t(d)],
                                                 sn[std::size_t(d)]);
                out.plane(d)[std::size_t(lr) * win.width + lc] = horizon_angle(t);
            }
        }
        if (options.progress) options.progress->advance(std::uint64_t(win.width) * options.directions);
    });
    return out;
}

}  // namespace ts::visibility
