// Exact horizons by sweeping lines of constant azimuth (after Timonen and Westerholm 2010),
// with the receiver's own near field marched exactly.
//
// For azimuth phi the grid is covered by parallel lines in (col, G) space (row_metrics.hpp),
// spaced 1/lines_per_texel texel apart across the sweep. Each line is sampled at every integer
// column (mostly east-west lines) or row (mostly north-south lines), the height interpolated
// linearly between the two texels the line passes between, plus blocker-only samples where the
// line crosses the other family of texel lines and midway between those points: the bilinear
// surface as a 1/4-texel raymarch sees it (a diagonal line would otherwise miss the saddle
// between a cell's other two corners). The line is walked from the far end (where the blockers
// are) towards phi's opposite, keeping the upper convex hull of the profile behind.
//
// Far field: a line sample's horizon is the tangent from it to the hull of the points at least
// near_field_texels behind it (DelayedHull: amortised O(1) insertion; the query walks from the
// previous tangent vertex), and each texel takes the tent-weighted mean of the far horizons
// of the line samples within one line spacing of it (tangents are averaged: exact on a plane;
// second order in the lateral offset elsewhere), if the samples that have a far field carry at
// least as much of its weight as those with nothing that far behind them (has_far_field).
//
// Near field: a texel centre is a crease of the bilinear surface, so the slope of the first
// texel or two changes abruptly with a lateral offset of a fraction of a texel; interpolating
// it from lines beside the texel erred by degrees on real DEMs. So the first near_field_texels
// are marched from the texel centre itself, exactly like the reference, and the horizon is the
// larger of the two. Measured in docs/visibility.md.
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

#include "core/util/compiler_hints.hpp"
#include "core/util/parallel_for.hpp"
#include "core/util/progress_bar.hpp"
#include "core/visibility/bilinear_march.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/exact_azimuth.hpp"
#include "core/visibility/fast_atan.hpp"
#include "core/visibility/profile_hull.hpp"
#include "core/visibility/receiver_setup.hpp"
#include "core/visibility/row_metrics.hpp"
#include "core/visibility/surface_sampling.hpp"
#include "core/visibility/sweep_geometry.hpp"
#include "core/visibility/sweep_lanes.hpp"

namespace ts::visibility {
namespace {

// One near-field step from a texel centre: offset, bilinear fractions, 1/distance, curvature
// drop. The slope of a step is float arithmetic, the same in the scalar and the vectorised
// march (so a band-limited caller sees the same near field as the full one).
struct NearStep {
    double dcol, drow;
    int col0, row0;
    float fc, fr;
    float inv_s, drop;
    double inv_s_d, drop_d;  // the same in double, for the early exit
};

// The bilinear surface from a step's 4 corners, as surface_sampling.hpp's bilinear_valid
// blends 4 valid corners (so flat ground stays exactly flat).
inline float near_height(float z00, float z10, float z01, float z11, float fc, float fr) {
    const float top = z00 + fc * (z10 - z00), bottom = z01 + fc * (z11 - z01);
    return top + fr * (bottom - top);
}

inline float near_slope(float zs, float z0, const NearStep& st) {
    return (zs - z0) * st.inv_s - st.drop;
}

// One near-field step for the receivers [begin, end) of a row: best = max(best, slope of the
// step's bilinear sample). p0 points at the step's upper-left corner for receiver 0 of the row;
// every corner exists and is valid (finish_rows checks). Compiled for AVX2 where the CPU has
// it; the loop is the same float arithmetic either way.
// clang-format off
TS_OPTIMIZE_O3 [[gnu::target_clones("avx2", "default")]]
// clang-format on
void near_step_row(const float* __restrict p0, int w, const float* __restrict z0, const NearStep& st, int begin, int end,
                   float* __restrict best) {
    const float* __restrict p1 = p0 + w;
    for (int lc = begin; lc < end; ++lc) {
        const float slope = near_slope(near_height(p0[lc], p0[lc + 1], p1[lc], p1[lc + 1], st.fc, st.fr), z0[lc], st);
        best[lc] = slope > best[lc] ? slope : best[lc];
    }
}

struct SweepContext {
    const terrain::HeightGrid& grid;
    const RowMetrics& metrics;
    ReceiverWindow win;
    double curvature;  // 1 / (2 R_eff) or 0
    int lines_per_texel;
};

// Receiver window bounds, inclusive.
int first_col(const SweepContext& cx) {
    return cx.win.col0;
}
int last_col(const SweepContext& cx) {
    return cx.win.col0 + cx.win.width - 1;
}
int first_row(const SweepContext& cx) {
    return cx.win.row0;
}
int last_row(const SweepContext& cx) {
    return cx.win.row0 + cx.win.height - 1;
}

// The numbers n of the sweep lines col*sn + G(row)*cs = n*h that can pass through the
// receiver window (the invariant is linear in col and G, so its extremes are at the window's
// corners), with one line of margin on each side.
std::pair<long, long> line_numbers(const SweepContext& cx, double cs, double sn, double h) {
    auto invariant = [&](int col, int row) { return col * sn + cx.metrics.g(row) * cs; };
    double i_min = invariant(first_col(cx), first_row(cx)), i_max = i_min;
    for (double v : {invariant(last_col(cx), first_row(cx)), invariant(first_col(cx), last_row(cx)),
                     invariant(last_col(cx), last_row(cx))})
        i_min = std::min(i_min, v), i_max = std::max(i_max, v);
    return {long(std::floor(i_min / h)) - 1, long(std::ceil(i_max / h)) + 1};
}

// The spacing h of the lines n (sweep_geometry.hpp, shared with the lane-parallel sweep).
double column_line_spacing(const SweepContext& cx, double cs) {
    return sweep_geometry::column_line_spacing(cx.metrics, cx.lines_per_texel, cs);
}
double row_line_spacing(const SweepContext& cx, double sn) {
    return sweep_geometry::row_line_spacing(cx.lines_per_texel, sn);
}

// Far-field horizon (its tangent) of a line sample at distance s with height z, then add the
// sample itself as a blocker; -infinity if nothing lies far enough behind it (splatted all the
// same: its weight counts against the far field of the texels beside it, has_far_field).
[[gnu::always_inline]] inline float far_horizon_at(DelayedHull::Line& hull, double s, float z, double curvature) {
    const double u = double(z) - curvature * s * s;
    const double slope = hull.query(s, u);
    hull.add(s, u);
    if (slope == ProfileHull::kNone) return -std::numeric_limits<float>::infinity();
    // tan(elevation): texels average tangents (equal to averaging angles to second order, and
    // exact on a plane), so the one atan per texel comes at the end.
    return float(slope - 2.0 * curvature * s);
}

// Points a line can add: a sample and at most 3 blockers per segment, one segment per sample.
std::size_t line_capacity(const terrain::HeightGrid& g) {
    return 4 * (std::size_t(std::max(g.width, g.height)) + 1);
}

using sweep_geometry::kEdgeSlack;
using sweep_geometry::kMinCrossing;

// bilinear_valid at (col, row) inside the grid, with its common case (4 valid corners, not on
// the last row or column) inline: the same arithmetic, so the same value. kVoidFree: the grid
// has no voids, so every corner is valid.
template <bool kVoidFree>
[[gnu::always_inline]] inline float surface_at(const terrain::HeightGrid& g, double col, double row) {
    const int c0 = int(col), r0 = int(row);
    if (c0 + 1 < g.width && r0 + 1 < g.height) {
        const float* p = g.z.data() + std::size_t(r0) * g.width + c0;
        const float z00 = p[0], z10 = p[1], z01 = p[g.width], z11 = p[g.width + 1];
        if (kVoidFree || (!std::isnan(z00) && !std::isnan(z10) && !std::isnan(z01) && !std::isnan(z11))) {
            const float fc = float(col - c0), fr = float(row - r0);
            const float top = z00 + fc * (z10 - z00), bottom = z01 + fc * (z11 - z01);
            return top + fr * (bottom - top);
        }
    }
    return bilinear_valid(g.z.data(), g.width, g.height, col, row);
}

// One blocker at fraction f of the segment from (col_a, row_a) to (col_b, row_b), which
// starts at distance s and is ds long; none where the surface is void.
template <bool kVoidFree>
[[gnu::always_inline]] inline void add_blocker(DelayedHull::Line& hull, const terrain::HeightGrid& g, double curvature,
                                               double s, double ds, double col_a, double row_a, double col_b,
                                               double row_b, double f) {
    const float z = surface_at<kVoidFree>(g, col_a + f * (col_b - col_a), row_a + f * (row_b - row_a));
    if (kVoidFree || !std::isnan(z)) hull.add(s + f * ds, double(z) - curvature * (s + f * ds) * (s + f * ds));
}

// Blocker-only points of the bilinear surface between two consecutive line samples a = (col,
// row) and b, at distances s and s + ds: where the segment crosses a texel row or column the
// surface has a height of its own, and inside a cell the surface along the segment is a
// quadratic (a diagonal line passes the saddle between the cell's other two corners), so the
// midpoint of each piece is added too. This is what a 1/4-texel raymarch sees.
// A column sweep's segment runs between two integer columns (kColumns; a row sweep's between
// two integer rows), so only the other coordinate, `across`, can cross a texel line; the first
// integer past the smaller end is the one crossing taken (the arithmetic of a general
// crossing test with std::ceil and std::min/max, for coordinates >= 0).
template <bool kColumns, bool kVoidFree>
[[gnu::always_inline]] inline void add_segment_blockers(DelayedHull::Line& hull, const terrain::HeightGrid& g,
                                                        double curvature, double s, double ds, double col_a,
                                                        double row_a, double col_b, double row_b) {
    const double a = kColumns ? row_a : col_a, b = kColumns ? row_b : col_b;
    const double lo = b < a ? b : a, hi = a < b ? b : a;
    const int lo_floor = int(lo);  // lo >= 0: the conversion floors
    double cut = 0;                // none
    if (double(lo_floor) != lo) {
        const double k = double(lo_floor + 1);  // std::ceil(lo)
        if (k < hi) {
            const double f = (k - a) / (b - a);
            if (f > kMinCrossing && f < 1 - kMinCrossing) cut = f;
        }
    }
    // The midpoint of the whole segment (0.5 * (0 + 1)), or the midpoint of the first piece,
    // the crossing and the midpoint of the second piece.
    if (cut == 0) {
        add_blocker<kVoidFree>(hull, g, curvature, s, ds, col_a, row_a, col_b, row_b, 0.5);
    } else {
        add_blocker<kVoidFree>(hull, g, curvature, s, ds, col_a, row_a, col_b, row_b, 0.5 * cut);
        add_blocker<kVoidFree>(hull, g, curvature, s, ds, col_a, row_a, col_b, row_b, cut);
        add_blocker<kVoidFree>(hull, g, curvature, s, ds, col_a, row_a, col_b, row_b, 0.5 * (cut + 1.0));
    }
}

// Adds a line sample's horizon to the texels it lies between. `across` (>= 0) is the
// fractional texel coordinate across the sweep (row for column sweeps, col for row sweeps).
template <bool kAcrossIsRow>
[[gnu::always_inline]] inline void splat(FarFieldSums& acc, const ReceiverWindow& win, int along, double across,
                                         float slope, double inv_spacing) {
    const int t0 = int(across);  // std::floor for across >= 0
    for (int t = t0; t <= t0 + 1; ++t) {
        const double w = 1.0 - std::abs(across - t) * inv_spacing;  // tent over the local line spacing
        if (w <= 0) continue;
        const int col = kAcrossIsRow ? along : t;
        const int row = kAcrossIsRow ? t : along;
        const int lc = col - win.col0, lr = row - win.row0;
        if (lc < 0 || lr < 0 || lc >= win.width || lr >= win.height) continue;
        acc.add(std::size_t(lr) * win.width + lc, float(w), slope);
    }
}

// The height of a line sample between two texels a and b (fraction t): lerp_valid, or its
// valid-corner arithmetic alone where the grid has no voids.
template <bool kVoidFree>
[[gnu::always_inline]] inline float sample_height(float a, float b, float t) {
    return kVoidFree ? a + t * (b - a) : lerp_valid(a, b, t);
}

// Lines sampled at every integer column (|d col| >= |d row| along the line).
// The two sweeps are compiled at -O3, as near_step_row: a few per cent faster (measured), and
// the same floating-point operations (no fast-math; no FMA on the baseline ISA).
template <bool kVoidFree>
TS_OPTIMIZE_O3 void sweep_columns(const SweepContext& cx, double phi, long n_begin, long n_end,
                                           FarFieldSums& acc) {
    const auto& g = cx.grid;
    const auto& metrics = cx.metrics;
    const double cs = std::cos(phi), sn = std::sin(phi);
    // Line n: col*sn + G(row)*cs = n*h, h chosen so lines are at most 1/lpt rows apart at fixed
    // col (closer where rho is larger: rows near a pole on a global grid).
    const double h = column_line_spacing(cx, cs);
    // Blockers lie towards +phi; walk from there so they are behind.
    const int step = cs > 0 ? -1 : 1;
    const int c_start = cs > 0 ? g.width - 1 : 0;
    // Stop past the window: nothing left to receive.
    const int c_stop = cs > 0 ? first_col(cx) - 1 : last_col(cx) + 1;
    const double gmax = metrics.g_max();
    const double abs_cs = std::abs(cs);
    const double abs_cs_over_h = abs_cs / h;  // 1 / line spacing across rows is this * rho
    const double curvature = cx.curvature;
    const std::size_t capacity = line_capacity(g);
    for (long n = n_begin; n < n_end; ++n) {
        DelayedHull::Line hull = acc.hull.begin_line(capacity);
        double s = 0, prev_row = -1;
        bool started = false;
        int row_hint = 0;
        for (int c = c_start; c != c_stop; c += step) {
            double gv = (double(n) * h - c * sn) / cs;
            if (gv < -kEdgeSlack || gv > gmax + kEdgeSlack) {
                if (started) break;  // the line has left the grid
                continue;
            }
            gv = std::clamp(gv, 0.0, gmax);  // a line on the grid's edge, up to rounding
            const double row = metrics.row_of_g(gv, row_hint);
            if (started) {
                const double ds = metrics.dx_at(0.5 * (row + prev_row)) / abs_cs;
                add_segment_blockers<true, kVoidFree>(hull, g, curvature, s, ds, c - step, prev_row, c, row);
                s += ds;
            }
            started = true;
            prev_row = row;
            const int r0 = std::min(int(row), g.height - 1);
            const float fr = float(row - r0);
            const float z =
                r0 + 1 < g.height ? sample_height<kVoidFree>(g.at(c, r0), g.at(c, r0 + 1), fr) : g.at(c, r0);
            if (std::isnan(z)) continue;  // inside a void: neither blocks nor receives
            const float slope = far_horizon_at(hull, s, z, curvature);
            if (c < first_col(cx) || c > last_col(cx)) continue;
            splat<true>(acc, cx.win, c, row, slope, abs_cs_over_h * metrics.rho(row));
        }
    }
}

// Lines sampled at every integer row.
template <bool kVoidFree>
TS_OPTIMIZE_O3 void sweep_rows(const SweepContext& cx, double phi, long n_begin, long n_end,
                                        FarFieldSums& acc) {
    const auto& g = cx.grid;
    const auto& metrics = cx.metrics;
    const double cs = std::cos(phi), sn = std::sin(phi);
    const double h = row_line_spacing(cx, sn);
    // North (sn > 0) is towards row 0: blockers at smaller rows, so walk rows upwards.
    const int step = sn > 0 ? 1 : -1;
    const int r_start = sn > 0 ? 0 : g.height - 1;
    const int r_stop = sn > 0 ? last_row(cx) + 1 : first_row(cx) - 1;
    const double abs_sn = std::abs(sn);
    const double curvature = cx.curvature;
    const double inv_spacing = double(cx.lines_per_texel);
    const std::size_t capacity = line_capacity(g);
    for (long n = n_begin; n < n_end; ++n) {
        DelayedHull::Line hull = acc.hull.begin_line(capacity);
        double s = 0, prev_col = -1;
        bool started = false;
        for (int r = r_start; r != r_stop; r += step) {
            double col = (double(n) * h - metrics.g(r) * cs) / sn;
            if (col < -kEdgeSlack || col > g.width - 1 + kEdgeSlack) {
                if (started) break;
                continue;
            }
            col = std::clamp(col, 0.0, double(g.width - 1));
            if (started) {
                const double ds = 0.5 * (metrics.dy(r) + metrics.dy(r - step)) / abs_sn;
                add_segment_blockers<false, kVoidFree>(hull, g, curvature, s, ds, prev_col, r - step, col, r);
                s += ds;
            }
            started = true;
            prev_col = col;
            const int c0 = std::min(int(col), g.width - 1);
            const float fc = float(col - c0);
            const float z = c0 + 1 < g.width ? sample_height<kVoidFree>(g.at(c0, r), g.at(c0 + 1, r), fc) : g.at(c0, r);
            if (std::isnan(z)) continue;
            const float slope = far_horizon_at(hull, s, z, curvature);
            if (r < first_row(cx) || r > last_row(cx)) continue;
            splat<false>(acc, cx.win, r, col, slope, inv_spacing);
        }
    }
}

}  // namespace

ExactAzimuthSweep::ExactAzimuthSweep(const terrain::HeightGrid& grid, const HorizonOptions& options)
    : grid_(grid),
      metrics_(grid),
      win_(resolve_window(grid, options.window)),
      curvature_(curvature_factor(options.curvature)),
      lines_per_texel_(std::max(1, options.exact_lines_per_texel)),
      z_top_(highest_height(grid)),
      simd_lines_(options.exact_simd_lines) {
    void_rows_before_.assign(std::size_t(grid.height) + 1, 0);
    for (int r = 0; r < grid.height; ++r) {
        bool has_void = false;
        for (int c = 0; c < grid.width; ++c) has_void |= std::isnan(grid.at(c, r));
        void_rows_before_[std::size_t(r) + 1] = void_rows_before_[std::size_t(r)] + (has_void ? 1 : 0);
    }
    // The near field in metres: near_field_texels of the grid's smallest spacing.
    double unit = std::numeric_limits<double>::infinity();
    for (int r = 0; r < grid.height; ++r) unit = std::min({unit, metrics_.dx(r), metrics_.dy(r)});
    near_m_ = std::max(0.0, options.exact_near_field_texels) * unit;
    // Per-tile tops dilated by one tile, when the near field fits (exact_azimuth.hpp). The
    // march moves at most near_field_texels texels along each axis (each step is a quarter of
    // the smaller spacing), and its bilinear corners one more.
    if (std::ceil(std::max(0.0, options.exact_near_field_texels)) + 2 <= kTile) {
        tiles_x_ = (grid.width + kTile - 1) / kTile;
        const int tiles_y = (grid.height + kTile - 1) / kTile;
        std::vector<float> top(std::size_t(tiles_x_) * tiles_y, -std::numeric_limits<float>::infinity());
        for (int r = 0; r < grid.height; ++r)
            for (int c = 0; c < grid.width; ++c) {
                const float v = grid.at(c, r);
                float& t = top[std::size_t(r / kTile) * tiles_x_ + c / kTile];
                if (v > t) t = v;  // NaN (void) never compares greater
            }
        block_top_.assign(top.size(), -std::numeric_limits<float>::infinity());
        for (int ty = 0; ty < tiles_y; ++ty)
            for (int tx = 0; tx < tiles_x_; ++tx) {
                float m = -std::numeric_limits<float>::infinity();
                for (int y = std::max(0, ty - 1); y <= std::min(tiles_y - 1, ty + 1); ++y)
                    for (int x = std::max(0, tx - 1); x <= std::min(tiles_x_ - 1, tx + 1); ++x)
                        m = std::max(m, top[std::size_t(y) * tiles_x_ + x]);
                block_top_[std::size_t(ty) * tiles_x_ + tx] = m;
            }
    }
}

SweepPlan ExactAzimuthSweep::plan(double phi) const {
    const SweepContext cx{grid_, metrics_, win_, curvature_, lines_per_texel_};
    const double cs = std::cos(phi), sn = std::sin(phi);
    SweepPlan p;
    p.phi = phi;
    // Sample along the axis the line crosses fastest, so samples are <= 1 texel apart.
    p.along_columns = std::abs(cs) >= std::abs(sn) / metrics_.mean_rho();
    const double h = p.along_columns ? column_line_spacing(cx, cs) : row_line_spacing(cx, sn);
    std::tie(p.n_min, p.n_max) = line_numbers(cx, cs, sn, h);
    return p;
}

FarFieldSums ExactAzimuthSweep::make_sums() const {
    FarFieldSums s{{}, {}, {}, DelayedHull(near_m_)};
    s.sum.assign(texels(), 0.0f);
    s.weight.assign(texels(), 0.0f);
    s.empty_weight.assign(texels(), 0.0f);
    return s;
}

void ExactAzimuthSweep::sweep_far_field(const SweepPlan& plan, long n_begin, long n_end, FarFieldSums& sums) const {
    const SweepContext cx{grid_, metrics_, win_, curvature_, lines_per_texel_};
    n_begin = std::max(n_begin, plan.n_min);
    n_end = std::min(n_end, plan.n_max + 1);
    // Whole groups of 8 lines as AVX-512 lanes, bit-identical (sweep_lanes.hpp); the rest here.
    if (simd_lines_)
        n_begin = sweep_lines_simd({grid_, metrics_, win_, curvature_, lines_per_texel_, near_m_}, plan, n_begin, n_end,
                                   sums);
    // A grid without voids (the common case) skips every void test of the sampling.
    const bool void_free = void_rows_before_.back() == 0;
    if (plan.along_columns)
        void_free ? sweep_columns<true>(cx, plan.phi, n_begin, n_end, sums)
                  : sweep_columns<false>(cx, plan.phi, n_begin, n_end, sums);
    else
        void_free ? sweep_rows<true>(cx, plan.phi, n_begin, n_end, sums)
                  : sweep_rows<false>(cx, plan.phi, n_begin, n_end, sums);
}

void ExactAzimuthSweep::finish_rows(double phi, const float* sum, const float* weight, const float* empty_weight,
                                    int lr_begin, int lr_end, float* plane, double band_lo, double band_hi) const {
    const auto& grid = grid_;
    const auto& metrics = metrics_;
    const auto& win = win_;
    const double cs = std::cos(phi), sn = std::sin(phi);
    const double near_m = near_m_;
    std::vector<NearStep> near_steps;
    std::vector<float> row_best(std::size_t(std::max(0, win.width)));
    const double wmax = grid.width - 1, hmax = grid.height - 1;
    const float* z = grid.z.data();
    const int w = grid.width;
    // Without a band every step counts, so interior rows take the vectorised march below.
    const bool whole_band =
        band_lo == -std::numeric_limits<double>::infinity() && band_hi == std::numeric_limits<double>::infinity();

    // One receiver, stepping as the reference does, with the exact early exits.
    auto march_texel = [&](int lr, int lc, double best) {
        const int row = win.row0 + lr, col = win.col0 + lc;
        const float z0 = grid.at(col, row);
        const float z_top = near_top(col, row);
        for (const NearStep& st : near_steps) {
            const double c = col + st.dcol, r = row + st.drow;
            if (best >= band_hi) break;  // above the band whatever follows
            if (c < -1e-7 || r < -1e-7 || c > wmax + 1e-7 || r > hmax + 1e-7) break;
            // Exact early exit: even the highest point in reach cannot raise the horizon
            // (into the band).
            if ((double(z_top) - z0) * st.inv_s_d - st.drop_d <= std::max(best, band_lo)) break;
            const int c0 = col + st.col0, r0 = row + st.row0;
            float zs = kNoHeight;
            if (c0 >= 0 && r0 >= 0 && c0 + 1 < w && r0 + 1 < grid.height) {
                const float* p = z + std::size_t(r0) * w + c0;
                zs = near_height(p[0], p[1], p[w], p[w + 1], st.fc, st.fr);
            }
            if (std::isnan(zs))  // a void corner or the grid's last row/column
                zs = bilinear_valid(z, w, grid.height, std::clamp(c, 0.0, wmax), std::clamp(r, 0.0, hmax));
            if (!std::isnan(zs)) best = std::max(best, double(near_slope(zs, z0, st)));
        }
        return best;
    };

    for (int lr = lr_begin; lr < lr_end; ++lr) {
        const int row = win.row0 + lr;
        // Near-field steps as the reference takes them (1/4 texel); over a few texels the
        // row's spacing is constant to 1e-5, so the steps are set up once per row. Since the
        // receivers are texel centres, every texel of the row shares each step's integer
        // offset and bilinear weights.
        const double dx = metrics.dx(row), dy = metrics.dy(row), ds = kMarchStepTexels * std::min(dx, dy);
        const double dc = cs * ds / dx, dr = -sn * ds / dy;
        const int steps = near_m > 0 ? int(near_m / ds + 1e-9) : 0;
        near_steps.resize(std::size_t(steps));
        int c_lo = 0, c_hi = 0, r_lo = 0, r_hi = 0;  // extreme integer offsets of the steps
        for (int k = 1; k <= steps; ++k) {
            NearStep& st = near_steps[std::size_t(k - 1)];
            st.dcol = k * dc;
            st.drow = k * dr;
            st.col0 = int(std::floor(st.dcol));
            st.row0 = int(std::floor(st.drow));
            st.fc = float(st.dcol - st.col0), st.fr = float(st.drow - st.row0);
            st.inv_s_d = 1.0 / (k * ds);
            st.drop_d = curvature_ * k * ds;
            st.inv_s = float(st.inv_s_d), st.drop = float(st.drop_d);
            c_lo = std::min(c_lo, st.col0), c_hi = std::max(c_hi, st.col0);
            r_lo = std::min(r_lo, st.row0), r_hi = std::max(r_hi, st.row0);
        }
        const std::size_t i_row = std::size_t(lr) * win.width;
        // Vectorised interior: texels whose every step reads 4 existing corners of void-free
        // rows. All steps are taken (the early exit only skips steps that cannot raise the
        // maximum, so the result is the same), as one SIMD loop over the row per step.
        int v_begin = 0, v_end = 0;
        if (whole_band && steps > 0 && row + r_lo >= 0 && row + r_hi + 1 < grid.height &&
            !voids_in_rows(row + r_lo, row + r_hi + 1)) {
            v_begin = std::clamp(-c_lo - win.col0, 0, win.width);
            v_end = std::clamp(w - 1 - c_hi - win.col0, v_begin, win.width);
        }
        if (v_end > v_begin) {
            float* __restrict best = row_best.data();
            const float* __restrict s_row = sum + i_row;
            const float* __restrict w_row = weight + i_row;
            const float* __restrict e_row = empty_weight + i_row;
            const float* __restrict z0 = z + std::size_t(row) * w + win.col0;
            for (int lc = v_begin; lc < v_end; ++lc)
                best[lc] = has_far_field(w_row[lc], e_row[lc]) ? s_row[lc] / w_row[lc]
                                                               : -std::numeric_limits<float>::infinity();
            for (const NearStep& st : near_steps)
                near_step_row(z + std::size_t(row + st.row0) * w + win.col0 + st.col0, w, z0, st, v_begin, v_end, best);
            for (int lc = v_begin; lc < v_end; ++lc) {
                const float b = best[lc];
                plane[i_row + lc] = b == -std::numeric_limits<float>::infinity() ? 0.0f : float(fast_atan(double(b)));
            }
        }
        for (int lc = 0; lc < win.width; ++lc) {
            if (lc == v_begin && v_end > v_begin) lc = v_end;
            if (lc >= win.width) break;
            const std::size_t i = i_row + lc;
            if (std::isnan(grid.at(win.col0 + lc, row))) {  // void receiver: no horizon at all
                plane[i] = std::numeric_limits<float>::quiet_NaN();
                continue;
            }
            const double far =
                has_far_field(weight[i], empty_weight[i]) ? double(sum[i] / weight[i]) : ProfileHull::kNone;
            const double best = march_texel(lr, lc, far);
            plane[i] = best == ProfileHull::kNone ? 0.0f : float(fast_atan(best));
        }
    }
}

HorizonSet exact_horizons(const terrain::HeightGrid& grid, const HorizonOptions& options) {
    const ExactAzimuthSweep sweep(grid, options);
    // finish_rows writes every texel of a plane (void receivers as NaN).
    HorizonSet out = unfilled_horizons(sweep.window(), options.directions);
    const int workers = std::min(thread_count(options.threads), options.directions);
    std::vector<FarFieldSums> scratch;
    for (int w = 0; w < workers; ++w) scratch.push_back(sweep.make_sums());
    // Row sweeps cost ~1.5x column sweeps (every sample reads a new grid row): hand them out
    // first, so the last items are the cheap ones and the workers finish together.
    std::vector<SweepPlan> plans;
    for (int d = 0; d < options.directions; ++d) plans.push_back(sweep.plan(azimuth_rad(d, options.directions)));
    std::vector<int> order(std::size_t(options.directions));
    for (int d = 0; d < options.directions; ++d) order[std::size_t(d)] = d;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return !plans[std::size_t(a)].along_columns && plans[std::size_t(b)].along_columns;
    });
    parallel_for(options.directions, workers, [&](int item, int worker) {
        const int d = order[std::size_t(item)];
        const SweepPlan& plan = plans[std::size_t(d)];
        FarFieldSums& acc = scratch[std::size_t(worker)];
        std::fill(acc.sum.begin(), acc.sum.end(), 0.0f);
        std::fill(acc.weight.begin(), acc.weight.end(), 0.0f);
        std::fill(acc.empty_weight.begin(), acc.empty_weight.end(), 0.0f);
        sweep.sweep_far_field(plan, plan.n_min, plan.n_max + 1, acc);
        sweep.finish_rows(plan.phi, acc.sum.data(), acc.weight.data(), acc.empty_weight.data(), 0, out.height,
                          out.plane(d));
        if (options.progress) options.progress->advance(out.texels());
    });
    return out;
}

}  // namespace ts::visibility
