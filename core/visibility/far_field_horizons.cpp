#include "core/visibility/far_field_horizons.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/visibility/bilinear_march.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/pyramid_shared.hpp"
#include "core/visibility/receiver_setup.hpp"
#include "core/visibility/sun_visibility.hpp"

namespace ts::visibility {
namespace {

constexpr double kNoSlope = -std::numeric_limits<double>::infinity();

void check_options(const FarFieldOptions& options) {
    if (!(options.start_texels >= 1)) throw InputError("far field: the start must be at least 1 texel");
    if (options.samples_per_octave < 1 || options.sun_samples_per_octave < 1)
        throw InputError("far field: at least 1 sample per octave");
}

// Texels along one side of a grid's level `shift` (each 2x2 step rounds up).
int level_size(int level0, int shift) {
    for (int k = 0; k < shift; ++k) level0 = (level0 + 1) / 2;
    return level0;
}

// A mean level of the grid (2x2 steps as the pyramid takes them) and its row spacing.
struct CoarseCopy {
    std::vector<float> z;
    int width = 0, height = 0;
    std::vector<double> dx_m, dy_m;
};

// `steps` more 2x2 steps from the level `from`; the first step reads `from` in place, so a
// whole grid is never copied.
CoarseCopy coarse_copy(const terrain::HeightGrid& from, int steps, int threads) {
    CoarseCopy c;
    c.width = from.width, c.height = from.height;
    c.dx_m = from.dx_m, c.dy_m = from.dy_m;
    if (steps == 0) c.z.assign(from.z.begin(), from.z.end());
    for (int k = 0; k < steps; ++k) {
        c.z = terrain::downsample_2x2(k == 0 ? from.z.data() : c.z.data(), c.width, c.height, false, threads);
        halve_row_spacing(c.dx_m, c.dy_m);
        c.width = (c.width + 1) / 2, c.height = int(c.dx_m.size());
    }
    return c;
}

// A grid of row spacing alone: what RowMetrics reads of a grid the far field never holds.
terrain::HeightGrid spacing_only(int width, int height, std::vector<double> dx_m, std::vector<double> dy_m) {
    terrain::HeightGrid g;
    g.width = width, g.height = height;
    g.dx_m = std::move(dx_m), g.dy_m = std::move(dy_m);
    return g;
}

}  // namespace

int FarField::coarse_shift_for(const FarFieldOptions& options, int width0, int height0) {
    check_options(options);
    // The first far sample of the denser schedule reads the finest level any sample reads (the
    // gap grows with tau).
    constexpr int kAnyLevels = 64;
    const int densest = std::max(options.samples_per_octave, options.sun_samples_per_octave);
    int shift = shared::ts_pyramid_sample_level(options.start_texels, std::exp2(1.0 / densest), kAnyLevels);
    while (shift > 0 && (std::max(width0, height0) >> shift) < 2) --shift;
    return shift;
}

void halve_row_spacing(std::vector<double>& dx_m, std::vector<double>& dy_m) {
    const int h = int(dx_m.size()), half = (h + 1) / 2;
    std::vector<double> dx(static_cast<std::size_t>(half)), dy(static_cast<std::size_t>(half));
    for (int r = 0; r < half; ++r) {
        const int r0 = 2 * r, r1 = std::min(2 * r + 1, h - 1);
        dx[std::size_t(r)] = dx_m[std::size_t(r0)] + dx_m[std::size_t(r1)];
        dy[std::size_t(r)] = dy_m[std::size_t(r0)] + dy_m[std::size_t(r1)];
    }
    dx_m = std::move(dx), dy_m = std::move(dy);
}

FarField::FarField(const terrain::HeightGrid& grid, const FarFieldOptions& options)
    : FarField(grid, 0, grid.width, grid.height, grid.dx_m, grid.dy_m, highest_height(grid), options) {}

FarField::FarField(const terrain::HeightGrid& coarse, int coarse_shift, int width0, int height0,
                   std::vector<double> dx0_m, std::vector<double> dy0_m, float z_top, const FarFieldOptions& options)
    : options_(options),
      width_(width0),
      height_(height0),
      shift_(std::max(coarse_shift_for(options, width0, height0), coarse_shift)),
      metrics_(spacing_only(width0, height0, std::move(dx0_m), std::move(dy0_m))),
      z_top_(z_top) {
    if (coarse_shift < 0 || coarse.width != level_size(width0, coarse_shift) ||
        coarse.height != level_size(height0, coarse_shift) ||
        coarse.z.size() != std::size_t(coarse.width) * std::size_t(coarse.height) ||
        coarse.dx_m.size() != std::size_t(coarse.height) || coarse.dy_m.size() != std::size_t(coarse.height))
        throw InputError("far field: the coarse copy is not level " + std::to_string(coarse_shift) + " of a " +
                         std::to_string(width0) + "x" + std::to_string(height0) + " grid");
    CoarseCopy copy = coarse_copy(coarse, shift_ - coarse_shift, options.threads);
    terrain::HeightGrid cg;
    cg.width = copy.width, cg.height = copy.height;
    cg.z = copy.z;
    cg.dx_m = std::move(copy.dx_m), cg.dy_m = std::move(copy.dy_m);
    terrain::PyramidOptions po;
    po.threads = options.threads;
    po.tile_size = 64;
    pyramid_ = terrain::HeightPyramid(cg, po);
    curvature_ = curvature_factor(options.curvature);
    const int levels = shift_ + pyramid_.level_count();
    const double max_tau = pyramid_max_tau(width_, height_);
    for (const PyramidSample& s : pyramid_samples(options.samples_per_octave, levels, max_tau))
        if (s.tau >= options.start_texels) samples_.push_back({s.tau, std::max(0, s.level - shift_)});
    for (const PyramidSample& s : pyramid_samples(options.sun_samples_per_octave, levels, max_tau))
        if (s.tau >= options.start_texels) sun_samples_.push_back({s.tau, std::max(0, s.level - shift_)});
}

std::size_t FarField::bytes() const {
    return pyramid_.memory_bytes() + (samples_.size() + sun_samples_.size()) * sizeof(PyramidSample) +
           2 * sizeof(double) * std::size_t(height_);
}

double FarField::far_slope(double col, double row, double z0, double phi) const {
    const int r = std::clamp(int(std::lround(row)), 0, height_ - 1);
    const double dx = metrics_.dx(r), dy = metrics_.dy(r), unit = std::min(dx, dy);
    return march(samples_, col, row, z0, std::cos(phi) * unit / dx, -std::sin(phi) * unit / dy, unit);
}

double FarField::march(const std::vector<PyramidSample>& samples, double col, double row, double z0, double step_c,
                       double step_r, double unit, double floor, double enough) const {
    const double wmax = width_ - 1, hmax = height_ - 1, inv_scale = 1.0 / coarse_scale();
    double best = kNoSlope;
    for (const PyramidSample& smp : samples) {
        const double c = col + smp.tau * step_c, r = row + smp.tau * step_r;
        if (c < -1e-7 || r < -1e-7 || c > wmax + 1e-7 || r > hmax + 1e-7) break;
        const double s = smp.tau * unit;
        if (shared::ts_pyramid_slope(z_top_, z0, s, curvature_) <= std::max(best, floor)) break;
        // Grid texel-centre coordinates to the coarse copy's (level `shift_` of the grid).
        const float z = pyramid_.level(smp.level).sample_level0_valid((c + 0.5) * inv_scale - 0.5, (r + 0.5) * inv_scale - 0.5);
        if (std::isnan(z)) continue;
        best = std::max(best, shared::ts_pyramid_slope(z, z0, s, curvature_));
        if (best >= enough) break;
    }
    return best;
}

void FarField::check_window(const ReceiverWindow& receivers, const terrain::HeightGrid& window,
                            const WindowOrigin& window_origin) const {
    const int c0 = window_origin.col0, r0 = window_origin.row0;
    if (c0 < 0 || r0 < 0 || c0 + window.width > width_ || r0 + window.height > height_)
        throw InputError("far field: the window lies outside the grid it was built on");
    if (receivers.col0 < c0 || receivers.row0 < r0 || receivers.col0 + receivers.width > c0 + window.width ||
        receivers.row0 + receivers.height > r0 + window.height)
        throw InputError("far field: receivers outside the window grid");
}

void FarField::limit_sun(double azimuth_deg, double elevation_deg, double sun_radius_rad, const ReceiverWindow& origin,
                         const ReceiverWindow& receivers, const terrain::HeightGrid& grid, float* vis) const {
    if (grid.width != width_ || grid.height != height_) throw InputError("far field: not the grid it was built on");
    limit_sun(azimuth_deg, elevation_deg, sun_radius_rad, origin, receivers, grid, {0, 0}, vis);
}

void FarField::limit_sun(double azimuth_deg, double elevation_deg, double sun_radius_rad, const ReceiverWindow& origin,
                         const ReceiverWindow& receivers, const terrain::HeightGrid& window,
                         const WindowOrigin& window_origin, float* vis) const {
    check_window(receivers, window, window_origin);
    if (receivers.col0 < origin.col0 || receivers.row0 < origin.row0 ||
        receivers.col0 + receivers.width > origin.col0 + origin.width)
        throw InputError("far field: receivers outside the sun visibility's window");
    const double phi = (90.0 - azimuth_deg) * kPi / 180.0, elevation = elevation_deg * kPi / 180.0;
    // A far horizon below this cannot touch the disc: skip the atan and the segment area.
    const double clear = std::tan(std::min(elevation - sun_radius_rad, kPi / 2 - 1e-6));
    const double dark = std::tan(std::min(elevation + sun_radius_rad, kPi / 2 - 1e-6));
    parallel_for(receivers.height, thread_count(options_.threads), [&](int lr, int) {
        const int row = receivers.row0 + lr;
        const double dx = metrics_.dx(row), dy = metrics_.dy(row), unit = std::min(dx, dy);
        const double step_c = std::cos(phi) * unit / dx, step_r = -std::sin(phi) * unit / dy;
        for (int lc = 0; lc < receivers.width; ++lc) {
            const int col = receivers.col0 + lc;
            const float z0 = window.at(col - window_origin.col0, row - window_origin.row0);
            float& v = vis[std::size_t(row - origin.row0) * std::size_t(origin.width) + std::size_t(col - origin.col0)];
            if (std::isnan(z0) || std::isnan(v) || v <= 0.0f) continue;
            const double best = march(sun_samples_, col, row, z0, step_c, step_r, unit, clear, dark);
            if (best == kNoSlope || best < clear) continue;
            v = std::min(v, float(sun_disc_visible_fraction(std::atan(best), elevation, sun_radius_rad)));
        }
    });
}

void FarField::raise(HorizonSet& set, const ReceiverWindow& origin, const ReceiverWindow& receivers,
                     const terrain::HeightGrid& grid) const {
    if (grid.width != width_ || grid.height != height_) throw InputError("far field: not the grid it was built on");
    raise(set, origin, receivers, grid, {0, 0});
}

void FarField::raise(HorizonSet& set, const ReceiverWindow& origin, const ReceiverWindow& receivers,
                     const terrain::HeightGrid& window, const WindowOrigin& window_origin) const {
    if (receivers.col0 < origin.col0 || receivers.row0 < origin.row0 ||
        receivers.col0 + receivers.width > origin.col0 + set.width ||
        receivers.row0 + receivers.height > origin.row0 + set.height)
        throw InputError("far field: receivers outside the horizon set's window");
    check_window(receivers, window, window_origin);
    const std::size_t nd = std::size_t(set.directions);
    std::vector<double> cos_phi(nd), sin_phi(nd);
    for (std::size_t d = 0; d < nd; ++d)
        cos_phi[d] = std::cos(azimuth_rad(int(d), set.directions)), sin_phi[d] = std::sin(azimuth_rad(int(d), set.directions));
    parallel_for(receivers.height, thread_count(options_.threads), [&](int lr, int) {
        const int row = receivers.row0 + lr;
        const double dx = metrics_.dx(row), dy = metrics_.dy(row), unit = std::min(dx, dy);
        std::vector<double> step_c(nd), step_r(nd);
        for (std::size_t d = 0; d < nd; ++d) step_c[d] = cos_phi[d] * unit / dx, step_r[d] = -sin_phi[d] * unit / dy;
        for (int lc = 0; lc < receivers.width; ++lc) {
            const int col = receivers.col0 + lc;
            const float z0 = window.at(col - window_origin.col0, row - window_origin.row0);
            if (std::isnan(z0)) continue;
            const std::size_t k = std::size_t(row - origin.row0) * std::size_t(set.width) + std::size_t(col - origin.col0);
            for (int d = 0; d < set.directions; ++d) {
                const double best = march(samples_, col, row, z0, step_c[std::size_t(d)], step_r[std::size_t(d)], unit);
                if (best == kNoSlope) continue;
                float& a = set.plane(d)[k];
                a = std::max(a, float(std::atan(best)));
            }
        }
    });
}

}  // namespace ts::visibility
