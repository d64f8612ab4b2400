// The slides' multi-resolution marching (Snyder and Nowrouzezahrai 2008): from each receiver,
// sample k lies tau_k = 2^(k / N) texels away (N = the schedule's samples per octave) and
// reads the mean pyramid level whose texel size matches the gap to the next sample, so far
// samples see prefiltered (averaged) terrain instead of aliasing single texels. It walks a
// straight grid line with the receiver row's spacing (on a geographic grid the drift from a
// true constant-azimuth line over the walk is far below this method's own error).
// The levels are core/terrain's HeightPyramid (voids skipped in the means), read with the
// same void-skipping bilinear surface as the other methods (sample_level0_valid). The sample list
// and per-sample formulas are shared with the GPU (pyramid_schedule.hpp, pyramid_shared.h).
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/terrain/height_pyramid.hpp"
#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/progress_bar.hpp"
#include "core/visibility/bilinear_march.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/pyramid_schedule.hpp"
#include "core/visibility/pyramid_shared.hpp"
#include "core/visibility/receiver_setup.hpp"
#include "core/visibility/row_metrics.hpp"

namespace ts::visibility {

HorizonSet pyramid_horizons(const terrain::HeightGrid& grid, const HorizonOptions& options) {
    const PyramidSchedule* schedule = find_pyramid_schedule(options.pyramid_schedule);
    if (!schedule) throw QuantityError(Quantity::pyramid_schedule, "", "unknown schedule '" + options.pyramid_schedule + "'");
    const RowMetrics metrics(grid);
    terrain::PyramidOptions pyramid_options;
    pyramid_options.threads = options.threads;
    const terrain::HeightPyramid pyramid(grid, pyramid_options);
    const ReceiverWindow win = resolve_window(grid, options.window);
    HorizonSet out = zero_horizons(win, options.directions);
    const double curvature = curvature_factor(options.curvature);
    const float z_top = highest_height(grid);
    const std::vector<PyramidSample> samples = pyramid_samples(
        schedule->samples_per_octave, pyramid.level_count(), pyramid_max_tau(grid.width, grid.height));
    const double wmax = grid.width - 1, hmax = grid.height - 1;

    parallel_for(win.height, thread_count(options.threads), [&](int lr, int) {
        const int row = win.row0 + lr;
        const double dx = metrics.dx(row), dy = metrics.dy(row), unit = std::min(dx, dy);
        for (int lc = 0; lc < win.width; ++lc) {
            const int col = win.col0 + lc;
            const float z0 = grid.at(col, row);
            if (std::isnan(z0)) continue;
            for (int d = 0; d < options.directions; ++d) {
                const double phi = azimuth_rad(d, options.directions);
                const double step_c = std::cos(phi) * unit / dx, step_r = -std::sin(phi) * unit / dy;
                double best = -std::numeric_limits<double>::infinity();
                for (const PyramidSample& smp : samples) {
                    const double c = col + smp.tau * step_c, r = row + smp.tau * step_r;
                    if (c < -1e-7 || r < -1e-7 || c > wmax + 1e-7 || r > hmax + 1e-7)
                        break;  // edge rows survive rounding
                    const double s = smp.tau * unit;
                    if (shared::ts_pyramid_slope(z_top, z0, s, curvature) <= best) break;
                    const float z = pyramid.level(smp.level).sample_level0_valid(c, r);
                    if (std::isnan(z)) continue;
                    best = std::max(best, shared::ts_pyramid_slope(z, z0, s, curvature));
                }
                out.plane(d)[std::size_t(lr) * win.width + lc] = horizon_angle(best);
            }
        }
        if (options.progress) options.progress->advance(std::uint64_t(win.width) * options.directions);
    });
    return out;
}

}  // namespace ts::visibility
