#include "gpu/visibility/gpu_visibility.hpp"
#include "gpu/visibility/gpu_limits.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "core/util/progress_bar.hpp"
#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"
#include "core/visibility/bilinear_march.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/row_metrics.hpp"
#include "gpu/batch.hpp"
#include "gpu/kernel.hpp"
#include "gpu/visibility/gpu_pyramid.hpp"
#include "gpu/visibility/horizon_products.hpp"

namespace ts::gpu::visibility {
namespace {

namespace vis = ts::visibility;

// Mirrors of the shaders' push-constant blocks (ints and floats, 4 bytes each, no padding).
struct SweepPush {
    std::int32_t width, height, col0, row0, win_w, win_h, columns, n_min, line_offset, span_base, chunk_lines,
        max_points, step, k_begin, k_end;
    float cs, sn, curvature, delay, mean_rho;
    float m_hi, m_lo, inv_hi, inv_lo;
};
// RowInfo and LineInfo of the shaders.
struct RowInfo {
    float dx, dy, g_hi, near_steps, g_lo, dg, pad0, pad1;
};
struct LineInfo {
    std::int32_t first, count;
    float nh_hi, nh_lo;
};
// WalkState of the sweep shader: a line's walk between passes.
constexpr VkDeviceSize kWalkStateBytes = 32 + 64 * 16;
// Line samples per sweep pass: llvmpipe ends an invocation's loops after 65535 iterations in
// all; a sample costs ~50 (plus hull / 16 for the rebase), so 128 samples stay far below.
constexpr long kPassSamples = 128;
// FarEntry of the shaders: 16 bytes per line and window position.
constexpr VkDeviceSize kFarEntryBytes = 16;

// A double as the sum of two floats (the shaders' double-float values).
struct SplitDouble {
    float hi, lo;
};
SplitDouble split_double(double v) {
    const float hi = float(v);
    return {hi, float(v - double(hi))};
}
struct FinishPush {
    std::int32_t width, height, col0, row0, win_w, win_h, columns, n_min, total_lines, d;
    float cs, sn, h, curvature, z_top, row_spacing;
    std::int32_t tiles_x;
};

constexpr std::uint32_t kLineGroup = 64;  // local_size_x of vis_exact_sweep.comp
constexpr std::uint32_t kTileW = 8, kTileH = 8;  // vis_exact_finish is 8 x 8
constexpr VkDeviceSize kHullBudget = VkDeviceSize(64) << 20;  // scratch for the lines' hulls

// One azimuth's set of sweep lines over a receiver window, computed in double exactly as
// sweep_columns / sweep_rows do (the GPU then walks each line in float).
struct SweepPlan {
    bool columns = true;
    double cs = 1, sn = 0, h = 1;
    long n_min = 0, n_max = -1;
    int start = 0, stop = 0, step = 1;
    long lines() const { return n_max - n_min + 1; }
};

// The first integer in [lo, hi] where a monotone (false..true) predicate holds; hi + 1 if none.
template <class Pred>
int first_true(int lo, int hi, Pred pred) {
    int a = lo, b = hi + 1;
    while (a < b) {
        const int mid = a + (b - a) / 2;
        if (pred(mid)) b = mid;
        else a = mid + 1;
    }
    return a;
}

// Which positions of its walk each line visits, as (first, count): the positions where the
// CPU sweep's on-grid test holds (in double, the same expression), which form one interval
// because the line's across coordinate is monotone along it.
void add_spans(const terrain::HeightGrid& g, const vis::RowMetrics& m, const SweepPlan& p,
               std::vector<LineInfo>& spans) {
    constexpr double kEdgeSlack = 1e-7;  // exact_horizons.cpp
    const int lo = std::min(p.start, p.stop - p.step), hi = std::max(p.start, p.stop - p.step);
    for (long n = p.n_min; n <= p.n_max; ++n) {
        auto across = [&](int a) {
            return p.columns ? (double(n) * p.h - a * p.sn) / p.cs : (double(n) * p.h - m.g(a) * p.cs) / p.sn;
        };
        const double top = p.columns ? m.g_max() : double(g.width - 1);
        const bool rising = across(hi) >= across(lo);
        auto not_below = [&](int a) { return !(across(a) < -kEdgeSlack); };
        auto not_above = [&](int a) { return !(across(a) > top + kEdgeSlack); };
        int first, last;  // the interval in increasing position
        if (rising) {
            first = first_true(lo, hi, not_below);
            last = first_true(lo, hi, [&](int a) { return !not_above(a); }) - 1;
        } else {
            first = first_true(lo, hi, not_above);
            last = first_true(lo, hi, [&](int a) { return !not_below(a); }) - 1;
        }
        const SplitDouble nh = split_double(double(n) * p.h);
        if (last < first) {
            spans.push_back({0, 0, nh.hi, nh.lo});
            continue;
        }
        spans.push_back({p.step > 0 ? first : last, last - first + 1, nh.hi, nh.lo});
    }
}

SweepPlan plan_sweep(const terrain::HeightGrid& g, const vis::RowMetrics& m, const vis::ReceiverWindow& win, int d,
                     int directions, int lines_per_texel) {
    SweepPlan p;
    const double phi = vis::azimuth_rad(d, directions);
    p.cs = std::cos(phi);
    p.sn = std::sin(phi);
    p.columns = std::abs(p.cs) >= std::abs(p.sn) / m.mean_rho();
    p.h = p.columns ? m.min_rho() * std::abs(p.cs) / lines_per_texel : std::abs(p.sn) / lines_per_texel;
    auto invariant = [&](double col, int row) { return col * p.sn + m.g(row) * p.cs; };
    const int c_lo = win.col0, c_hi = win.col0 + win.width - 1;
    const int r_lo = win.row0, r_hi = win.row0 + win.height - 1;
    double i_min = invariant(c_lo, r_lo), i_max = i_min;
    for (double v : {invariant(c_hi, r_lo), invariant(c_lo, r_hi), invariant(c_hi, r_hi)})
        i_min = std::min(i_min, v), i_max = std::max(i_max, v);
    p.n_min = long(std::floor(i_min / p.h)) - 1;
    p.n_max = long(std::ceil(i_max / p.h)) + 1;
    if (p.columns) {
        p.step = p.cs > 0 ? -1 : 1;
        p.start = p.cs > 0 ? g.width - 1 : 0;
        p.stop = p.cs > 0 ? c_lo - 1 : c_hi + 1;
    } else {
        p.step = p.sn > 0 ? 1 : -1;
        p.start = p.sn > 0 ? 0 : g.height - 1;
        p.stop = p.sn > 0 ? r_hi + 1 : r_lo - 1;
    }
    return p;
}

// How the heights are split by rows into storage buffers (vis_surface.glsl's height_at).
struct HeightParts {
    int parts = 1, rows_per_part = 0;
};

struct Kernels {
    Kernel sweep, finish;
    Kernels(const Context& c, const HeightParts& hp)
        : sweep(c, "vis_exact_sweep",
                {.storage_buffers = 6 + kMaxHeightParts - 1,
                 .push_constant_bytes = sizeof(SweepPush),
                 .specialization = {std::uint32_t(hp.parts), std::uint32_t(hp.rows_per_part)}}),
          finish(c, "vis_exact_finish",
                 {.storage_buffers = 4 + kMaxHeightParts - 1 + 1,
                  .push_constant_bytes = sizeof(FinishPush),
                  .specialization = {std::uint32_t(hp.parts), std::uint32_t(hp.rows_per_part)}}) {}
};

// Bytes of the far-field buffer a band needs (the largest azimuth's lines x window positions).
VkDeviceSize far_bytes(const std::vector<SweepPlan>& plans, const vis::ReceiverWindow& band) {
    VkDeviceSize most = 0;
    for (const auto& p : plans)
        most = std::max(most, VkDeviceSize(p.lines()) * VkDeviceSize(p.columns ? band.width : band.height) *
                                  kFarEntryBytes);
    return most;
}

}  // namespace

Result compute(const Context& context, const terrain::HeightGrid& grid, const Options& options) {
    const auto& ho = options.horizon;
    if (grid.width < 1 || grid.height < 1 || grid.z.size() != std::size_t(grid.width) * std::size_t(grid.height))
        throw InputError("height grid: empty or inconsistent size");
    if (ho.method == vis::HorizonMethod::pyramid) return compute_pyramid(context, grid, options);  // gpu_pyramid.cpp
    if (ho.method != vis::HorizonMethod::exact)
        throw QuantityError(Quantity::visibility_method, std::string(vis::method_name(ho.method)),
                            "only exact runs on the GPU so far (compute on the CPU)");
    if (ho.directions < 1 || ho.directions > 4096)
        throw QuantityError(Quantity::directions, "", "must be between 1 and 4096, got " + std::to_string(ho.directions));
    // The log-SH shader loops ~17 times per direction, and llvmpipe ends an invocation's loops
    // after 65535 iterations in all.
    if (ho.directions > kMaxGpuDirections)
        throw QuantityError(Quantity::directions, "", "the GPU path takes at most " + std::to_string(kMaxGpuDirections) +
                                                          ", got " + std::to_string(ho.directions) + " (compute on the CPU)");
    if (options.log_sh && ho.directions < 4)
        throw QuantityError(Quantity::sh_output, "", "needs at least 4 directions, got " + std::to_string(ho.directions));
    const VkDeviceSize range = context.limits().maxStorageBufferRange;
    const VkDeviceSize height_range =
        options.max_height_buffer_bytes > 0 ? std::min<VkDeviceSize>(range, options.max_height_buffer_bytes) : range;
    // Heights: whole rows per storage buffer, at most kMaxHeightParts buffers.
    HeightParts hp;
    hp.rows_per_part = int(std::min<VkDeviceSize>(VkDeviceSize(grid.height),
                                                  height_range / (VkDeviceSize(grid.width) * sizeof(float))));
    if (hp.rows_per_part < 1 || (grid.height + hp.rows_per_part - 1) / hp.rows_per_part > kMaxHeightParts)
        throw InputError("height grid: " + std::to_string(grid.width) + "x" + std::to_string(grid.height) +
                         " needs more than " + std::to_string(kMaxHeightParts) + " GPU storage buffers of " +
                         std::to_string(height_range >> 20) + " MiB; crop it or compute on the CPU");
    hp.parts = (grid.height + hp.rows_per_part - 1) / hp.rows_per_part;

    const vis::RowMetrics metrics(grid);
    const vis::ReceiverWindow win = vis::resolve_window(grid, ho.window);
    const int directions = ho.directions;
    const int lpt = std::max(1, ho.exact_lines_per_texel);
    const double curvature = vis::curvature_factor(ho.curvature);
    double unit = std::numeric_limits<double>::infinity();
    for (int r = 0; r < grid.height; ++r) unit = std::min({unit, metrics.dx(r), metrics.dy(r)});
    const double near_m = std::max(0.0, ho.exact_near_field_texels) * unit;
    const float z_top = vis::highest_height(grid);
    // The near field's early exit: the top of the 3 x 3 blocks of kTopTile texels around each
    // block (as the CPU's ExactAzimuthSweep), when the march and its bilinear corners stay inside.
    constexpr int kTopTile = 16;  // vis_exact_finish.comp
    int tiles_x = 0;
    std::vector<float> block_top(1, z_top);
    if (std::ceil(std::max(0.0, ho.exact_near_field_texels)) + 2 <= kTopTile) {
        tiles_x = (grid.width + kTopTile - 1) / kTopTile;
        const int tiles_y = (grid.height + kTopTile - 1) / kTopTile;
        std::vector<float> top(std::size_t(tiles_x) * std::size_t(tiles_y), -std::numeric_limits<float>::infinity());
        for (int r = 0; r < grid.height; ++r)
            for (int c = 0; c < grid.width; ++c) {
                const float v = grid.at(c, r);
                float& t = top[std::size_t(r / kTopTile) * std::size_t(tiles_x) + std::size_t(c / kTopTile)];
                if (v > t) t = v;  // a void (NaN) never compares greater
            }
        block_top.assign(top.size(), -std::numeric_limits<float>::infinity());
        for (int ty = 0; ty < tiles_y; ++ty)
            for (int tx = 0; tx < tiles_x; ++tx) {
                float m = -std::numeric_limits<float>::infinity();
                for (int y = std::max(0, ty - 1); y <= std::min(tiles_y - 1, ty + 1); ++y)
                    for (int x = std::max(0, tx - 1); x <= std::min(tiles_x - 1, tx + 1); ++x)
                        m = std::max(m, top[std::size_t(y) * std::size_t(tiles_x) + std::size_t(x)]);
                block_top[std::size_t(ty) * std::size_t(tiles_x) + std::size_t(tx)] = m;
            }
    }

    // Per row: spacing (east-west floored as RowMetrics does), G, and the near field's step
    // count, all in double here so the GPU takes the CPU's decisions.
    std::vector<RowInfo> rows(std::size_t(grid.height));
    for (int r = 0; r < grid.height; ++r) {
        const double ds = vis::kMarchStepTexels * std::min(metrics.dx(r), metrics.dy(r));
        const SplitDouble g = split_double(metrics.g(r));
        const double dg = r + 1 < grid.height ? metrics.g(r + 1) - metrics.g(r) : 1.0;
        rows[std::size_t(r)] = {float(metrics.dx(r)), float(metrics.dy(r)), g.hi,
                                float(near_m > 0 ? int(near_m / ds + 1e-9) : 0), g.lo, float(dg), 0.0f, 0.0f};
    }

    // Bands of receiver rows: every per-band buffer within the storage-buffer range.
    const VkDeviceSize per_row = VkDeviceSize(win.width) * 4 * VkDeviceSize(std::max(directions, 16));
    int band_rows = int(std::min<VkDeviceSize>(VkDeviceSize(win.height), std::max<VkDeviceSize>(1, range / per_row)));
    if (options.max_band_rows > 0) band_rows = std::min(band_rows, options.max_band_rows);
    auto band_plans = [&](const vis::ReceiverWindow& band) {
        std::vector<SweepPlan> plans;
        for (int d = 0; d < directions; ++d) plans.push_back(plan_sweep(grid, metrics, band, d, directions, lpt));
        return plans;
    };
    while (band_rows > 1 &&
           far_bytes(band_plans({win.col0, win.row0, win.width, band_rows}), {win.col0, win.row0, win.width, band_rows}) >
               range)
        band_rows = (band_rows + 1) / 2;

    const int max_along = std::max(grid.width, grid.height);
    // A line gets at most 6 points per step: its sample and 5 blocker-only points between.
    const std::int32_t max_points = 6 * max_along + 8;
    const VkDeviceSize hull_line_bytes = VkDeviceSize(max_points) * 8;
    const VkDeviceSize hull_budget = std::min(kHullBudget, range);
    const long chunk_cap = long(std::max<VkDeviceSize>(kLineGroup, hull_budget / hull_line_bytes / kLineGroup * kLineGroup));

    const Kernels kernels(context, hp);
    const auto wall_start = std::chrono::steady_clock::now();
    Batch batch(context);
    Result result;
    HorizonProducts products(context, batch, options, win.width, win.height, result);
    std::vector<Buffer> height_parts;
    for (int i = 0; i < hp.parts; ++i) {
        const std::size_t first = std::size_t(i) * std::size_t(hp.rows_per_part) * std::size_t(grid.width);
        const std::size_t count =
            std::min(std::size_t(hp.rows_per_part), std::size_t(grid.height - i * hp.rows_per_part)) *
            std::size_t(grid.width);
        height_parts.push_back(batch.upload_new(grid.z.subspan(first, count)));
    }
    const Buffer& heights = height_parts[0];
    // Parts 1..3 as the shaders bind them (part 0 again where a part does not exist).
    auto part = [&](int i) -> const Buffer& { return i < hp.parts ? height_parts[std::size_t(i)] : heights; };
    const Buffer row_buffer = batch.upload_new(std::span<const RowInfo>(rows));
    const Buffer top_buffer = batch.upload_new(std::span<const float>(block_top));
    batch.mark("upload");
    batch.submit_and_wait();
    add_stage_times(result.stages, batch);

    for (int band_row0 = 0; band_row0 < win.height; band_row0 += band_rows) {
        const vis::ReceiverWindow band{win.col0, win.row0 + band_row0, win.width,
                                       std::min(band_rows, win.height - band_row0)};
        const auto plans = band_plans(band);
        const std::size_t band_texels = std::size_t(band.width) * std::size_t(band.height);
        long most_lines = 0;
        for (const auto& p : plans) most_lines = std::max(most_lines, p.lines());
        const long chunk = std::min(chunk_cap, most_lines);
        const Buffer hull = context.create_buffer(VkDeviceSize(chunk) * hull_line_bytes);
        const Buffer states = context.create_buffer(VkDeviceSize(chunk) * kWalkStateBytes);
        const Buffer far = context.create_buffer(far_bytes(plans, band));
        const Buffer horizons = context.create_buffer(band_texels * std::size_t(directions) * sizeof(float));
        std::vector<LineInfo> spans;
        std::vector<long> span_base;
        for (const auto& p : plans) {
            span_base.push_back(long(spans.size()));
            add_spans(grid, metrics, p, spans);
        }
        const Buffer span_buffer = batch.upload_new(std::span<const LineInfo>(spans));

        constexpr int kAzimuthsPerSubmit = 4;
        std::size_t reported = 0;  // rays of this band already on the progress bar
        for (int d = 0; d < directions; ++d) {
            const SweepPlan& p = plans[std::size_t(d)];
            const SplitDouble mult = split_double(p.columns ? p.sn : p.cs);
            const SplitDouble inv = split_double(1.0 / (p.columns ? p.cs : p.sn));
            batch.fill(far, 0x7fc00000u);  // every entry "no sample" (slope NaN)
            for (long first = 0; first < p.lines(); first += chunk) {
                const long n = std::min(chunk, p.lines() - first);
                long longest = 0;
                for (long l = first; l < first + n; ++l)
                    longest = std::max(longest, long(spans[std::size_t(span_base[std::size_t(d)] + l)].count));
                for (long k0 = 0; k0 < longest; k0 += kPassSamples) {
                    const SweepPush push{grid.width,
                                         grid.height,
                                         band.col0,
                                         band.row0,
                                         band.width,
                                         band.height,
                                         p.columns ? 1 : 0,
                                         std::int32_t(p.n_min),
                                         std::int32_t(first),
                                         std::int32_t(span_base[std::size_t(d)]),
                                         std::int32_t(n),
                                         max_points,
                                         p.step,
                                         std::int32_t(k0),
                                         std::int32_t(k0 + kPassSamples),
                                         float(p.cs),
                                         float(p.sn),
                                         float(curvature),
                                         float(near_m),
                                         float(metrics.mean_rho()),
                                         mult.hi,
                                         mult.lo,
                                         inv.hi,
                                         inv.lo};
                    batch.dispatch(kernels.sweep, {heights, row_buffer, hull, far, span_buffer, states, part(1), part(2), part(3)}, push,
                                   groups_for(std::uint64_t(n), kLineGroup));
                }
            }
            batch.mark("sweep");
            const FinishPush push{grid.width,
                                  grid.height,
                                  band.col0,
                                  band.row0,
                                  band.width,
                                  band.height,
                                  p.columns ? 1 : 0,
                                  std::int32_t(p.n_min),
                                  std::int32_t(p.lines()),
                                  d,
                                  float(p.cs),
                                  float(p.sn),
                                  float(p.h),
                                  float(curvature),
                                  z_top,
                                  float(1.0 / lpt),
                                  tiles_x};
            batch.dispatch(kernels.finish, {heights, row_buffer, far, horizons, part(1), part(2), part(3), top_buffer}, push,
                           groups_for(std::uint64_t(band.width), std::uint64_t(band.height), kTileW, kTileH));
            batch.mark("finish");
            // Two marks per azimuth and at most 63 per batch; every 4 azimuths a submit, so the
            // progress bar moves during a band (a whole DEM is often one band: on lavapipe
            // tens of seconds with no sign of life otherwise).
            if ((d + 1) % kAzimuthsPerSubmit == 0 && d + 1 < directions) {
                batch.submit_and_wait();
                add_stage_times(result.stages, batch);
                if (options.horizon.progress) {
                    options.horizon.progress->advance(band_texels * std::size_t(kAzimuthsPerSubmit));
                    reported += band_texels * std::size_t(kAzimuthsPerSubmit);
                }
            }
        }

        products.finish_band(batch, horizons, band_row0, band_texels, result, reported);
    }
    result.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall_start).count();
    return result;
}

}  // namespace ts::gpu::visibility
