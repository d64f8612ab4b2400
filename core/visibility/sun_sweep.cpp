// The sun sweep (sun_sweep.hpp): shadow heights along the exact path's lines of constant
// azimuth for the far field, the exact near-field march from each texel centre, then the disc.
#include "core/visibility/sun_sweep.hpp"

#include <algorithm>
#include <atomic>
#include <barrier>
#include <cmath>
#include <limits>
#include <string>
#include <thread>
#include <utility>

#include "core/geo/azimuth.hpp"
#include "core/util/angles.hpp"
#include "core/util/compiler_hints.hpp"
#include "core/util/error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/visibility/bilinear_march.hpp"
#include "core/visibility/earth_curvature.hpp"
#include "core/visibility/sun_sweep_shared.hpp"
#include "core/visibility/sun_visibility.hpp"
#include "core/visibility/surface_sampling.hpp"

namespace ts::visibility {

// One sun position's sweep: lines col*sn + G(row)*cs = n*h for n in [n_min, n_max], walked
// one column (column sweeps) or row (row sweeps) at a time from the sun's side of the grid.
struct SunShadowSweep::Frame {
    double cs = 1, sn = 0;
    bool along_columns = true;
    double h = 1;
    long n_min = 0, n_max = -1;
    double tan_e = 0, curv = 0;
    int delay = 1;  // the far field takes line samples at least this many steps behind
    int outer_start = 0, outer_step = 1, outer_count = 0;
    long line_margin = 2;  // lines a step can move across the grid's edge, plus slack
    // The sun's disc: centre elevation and radius (radians), tangents of its lowest and highest
    // points (a horizon below the first sees all of it, above the second none).
    double elevation = 0, radius = 0;
    float tan_lo = 0, tan_hi = 0;
    // The band the near field marches for: the disc's, or kSunHorizonBandRad about its centre
    // when the horizon itself is asked for (compute's `horizon_above_sun`).
    float march_lo = 0, march_hi = 0;
    float* horizon_out = nullptr;  // [row * width + col]: h - e, clamped to the band; or null
};

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// One near-field step from a texel centre, shared by every texel of a row (as in the exact
// path's finish_rows): integer offset, bilinear weights, 1/distance, curvature drop.
struct NearStep {
    double dcol, drow;
    int col0, row0;
    float w00, w10, w01, w11;
    float inv_s, drop;
    float dist;  // metres from the texel centre
};

// Hot loops are compiled twice, for x86-64-v3 (AVX2, FMA) and baseline x86-64, and picked at
// load time, so one binary runs anywhere and uses the wider vectors where the CPU has them.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
#define TS_SUN_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define TS_SUN_CLONES
#endif

constexpr float kNoShadow = -std::numeric_limits<float>::infinity();

// Where the lines of one column or row cross it: line n at lateral index base + n * per_line
// (clamped to [0, top]; in G for column sweeps, turned into a row through the row_of_g table).
struct LineGather {
    double base, per_line, top;
    long n_begin;
    const double* row_at_g;  // row_of_g at steps of g_step, and its last usable entry
    int row_at_g_last;
    double inv_g_step, gmax;
    int lateral;           // >= 2
    const float* lat;      // the column or row's heights
    const float* step_m;   // column sweeps: one column's step along a line, per row
};

// The far-field tangent of texels [i_lo, i_hi] of one column or row (those whose lower line
// n = floor(u) is in [n_begin, n_end)): the tent-weighted mean of the two lines' tangents
// (lines without a far field or on a void, NaN, do not count). Line number of texel i:
// u = (o sn + G(i) cs) / h on a column, (i sn + G(o) cs) / h on a row.
struct TentLines {
    double o_sn, g_cs, sn, cs, h;
    const double* g_row;  // G per row
    long n_begin, n_end;
    const float* tangent;  // [n - n_begin]
    float* dst;            // [i]
};
template <bool kColumns>
TS_SUN_CLONES void tent_lines(const TentLines& t, int i_lo, int i_hi) {
    const double inv_h = 1.0 / t.h;
    auto line = [&](int i) { return kColumns ? (t.o_sn + t.g_row[i] * t.cs) * inv_h : (i * t.sn + t.g_cs) * inv_h; };
    auto ours = [&](int i) {
        const long jn = long(std::floor(line(i)));
        return jn >= t.n_begin && jn < t.n_end;
    };
    // u is monotone in i, so our texels are a contiguous range: trim the ends, then the loop
    // stores unconditionally (and vectorises).
    while (i_lo <= i_hi && !ours(i_lo)) ++i_lo;
    while (i_hi >= i_lo && !ours(i_hi)) --i_hi;
    const float* __restrict tan_line = t.tangent - t.n_begin;
    float* __restrict dst = t.dst;
    for (int i = i_lo; i <= i_hi; ++i) {
        const double u = line(i);
        const double fl = std::floor(u);
        const int jn = int(fl);  // int, not long: AVX2 converts doubles to 32-bit integers only
        const float wt = float(u - fl);
        const float t0 = tan_line[jn], t1 = tan_line[jn + 1];
        const bool v0 = !std::isnan(t0), v1 = !std::isnan(t1);
        const float sum = (v0 ? (1 - wt) * t0 : 0.0f) + (v1 ? wt * t1 : 0.0f);
        const float wsum = (v0 ? 1 - wt : 0.0f) + (v1 ? wt : 0.0f);
        // Both lines valid (the common case): the weights sum to 1, no division.
        dst[i] = (v0 & v1) ? sum : wsum > 0 ? sum / wsum : -std::numeric_limits<float>::infinity();
    }
}

// Heights (linear between the two texels beside) of lines [jb, jb + count) on this column or
// row, and for column sweeps their step lengths (the step varies with the row).
template <bool kVoids, bool kColumns>
TS_SUN_CLONES void gather_lines(const LineGather& g, long jb, long je, float* __restrict zs, float* __restrict dsv) {
    const int last = g.lateral - 2;
    const double* tab = g.row_at_g;
    const float* lat = g.lat;
    for (long j = jb; j < je; ++j) {
        const double along = std::clamp(g.base + double(g.n_begin + j) * g.per_line, 0.0, g.top);
        double pos = along;
        if constexpr (kColumns) {
            const double x = std::min(along, g.gmax) * g.inv_g_step;
            const int k = std::min(int(x), g.row_at_g_last);
            pos = tab[k] + (x - double(k)) * (tab[k + 1] - tab[k]);
        }
        const int i0 = std::min(int(pos), last);
        const float fr = float(pos - i0);
        if constexpr (kVoids)
            zs[j] = lerp_valid(lat[i0], lat[i0 + 1], fr);
        else
            zs[j] = lat[i0] + fr * (lat[i0 + 1] - lat[i0]);
        if constexpr (kColumns) dsv[j] = g.step_m[i0] + fr * (g.step_m[i0 + 1] - g.step_m[i0]);
    }
}

// One step of lines [jb, je) of a sweep at outer step k: the shadow height S and its occluder
// distance carried one step (ds) on, the sample `delay` steps back (queued) and the midpoint
// of the segment after it (towards next) competing for S, this step's height zs queued, and the
// horizon tangent of the occluder setting S seen from zs. Branch-free over contiguous arrays
// so it vectorises: every candidate is computed and then selected.
template <bool kVoids>
TS_SUN_CLONES void advance_lines(long jb, long je, int k, int delay, float tan_e, float curv,
                                 const float* __restrict zs, const float* __restrict dsv, float* __restrict queued,
                                 const float* __restrict next, float* __restrict shadow, float* __restrict dist,
                                 float* __restrict tangent, int* __restrict start) {
    const float fdelay = float(delay);
    // Operators without short-circuit below: each comparison is computed unconditionally, so
    // GCC can if-convert the loop (an ordered compare counts as trapping otherwise).
    for (long j = jb; j < je; ++j) {
        const float zl = zs[j], ds = dsv[j], q = queued[j], nx = next[j];
        const int st0 = start[j];
        const bool first = st0 < 0;  // the line's first sample: nothing behind it yet
        const int st = first ? k : st0;
        float sh = shadow[j], d = dist[j];
        // -infinity (no shadow) stays so; its distance is never read.
        sh -= shared::ts_shadow_drop(d, ds, tan_e, curv);
        d += ds;
        const bool behind = !first & (k - st >= delay) & (!kVoids | !std::isnan(q));
        const float dd = fdelay * ds;
        const float cand = shared::ts_shadow_height(q, dd, tan_e, curv);
        const bool take = behind & (cand > sh);
        sh = take ? cand : sh;
        d = take ? dd : d;
        // The midpoint of the segment after it, as the exact path's mid-segment blockers: under
        // curvature it can stand above both ends (by c ds^2 / 4, ~200 m on a 1-degree grid,
        // 1e-5 m on a 30 m one).
        const float dm = dd - 0.5f * ds;
        const float mid = shared::ts_shadow_height(0.5f * (q + nx), dm, tan_e, curv);
        const bool take_mid = behind & (!kVoids | !std::isnan(nx)) & (mid > sh);
        sh = take_mid ? mid : sh;
        d = take_mid ? dm : d;
        sh = first ? kNoShadow : sh;
        d = first ? dist[j] : d;
        queued[j] = zl;
        shadow[j] = sh;
        dist[j] = d;
        start[j] = st;
        const float t = shared::ts_shadow_tangent(sh, zl, d, tan_e);
        tangent[j] = ((kVoids & std::isnan(zl)) | (sh == kNoShadow)) ? kNaN : t;
    }
}

}  // namespace

SunShadowSweep::SunShadowSweep(const terrain::HeightGrid& grid, const SunSweepOptions& options)
    : grid_(grid), options_(options), metrics_(grid) {
    const int w = grid.width, h = grid.height;
    if (grid.z.size() != std::size_t(w) * std::size_t(h))
        throw InputError("height grid: empty or inconsistent size");
    if (!(options.sun_radius_rad >= 0) || options.sun_radius_rad > 0.1)
        throw InputError("sun radius: must be between 0 and 0.1 rad, got " + std::to_string(options.sun_radius_rad));
    if (!(options.near_field_texels >= 0) || options.near_field_texels > 16)
        throw InputError("sun sweep: near field must be between 0 and 16 texels, got " +
                         std::to_string(options.near_field_texels));
    if (!(options.near_field_step_texels >= kMarchStepTexels) || options.near_field_step_texels > 4 ||
        !(options.near_field_fine_texels >= 0))
        throw InputError("sun sweep: near-field step must be between 0.25 and 4 texels and the fine part >= 0");
    double unit = std::numeric_limits<double>::infinity();
    for (int r = 0; r < h; ++r) unit = std::min({unit, metrics_.dx(r), metrics_.dy(r)});
    near_m_ = options.near_field_texels * unit;
    // row_of_g at G steps of the smallest rho (about a row), linear in between: the lines of a
    // column sweep are min_rho apart in G, so this is within ~1e-6 row of the exact inverse on
    // a geographic grid (rho varies as 1/cos(latitude)) and exact on a projected one.
    g_step_ = metrics_.min_rho();
    const std::size_t entries = std::size_t(metrics_.g_max() / g_step_) + 2;
    row_at_g_.resize(entries);
    for (std::size_t k = 0; k < entries; ++k) {
        const double gv = double(k) * g_step_;  // past the last row: extrapolated, for the lerp
        row_at_g_[k] = gv <= metrics_.g_max() ? metrics_.row_of_g(gv)
                                              : (h - 1) + (gv - metrics_.g_max()) / metrics_.rho(h - 1);
    }

    transposed_.resize(texels());
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) transposed_[std::size_t(c) * h + r] = grid.at(c, r);

    // Texels whose near-field march can touch a void (or is one) take the scalar path, which
    // skips void samples as the exact path does: a box of the march's reach plus its corners.
    const int reach = int(std::ceil(options.near_field_texels)) + 2;
    std::vector<std::uint8_t> rows_dilated(texels(), 0);
    for (int r = 0; r < h; ++r) {
        int last_void = -1'000'000;
        std::vector<int> next_void(std::size_t(w) + 1, 2'000'000);
        for (int c = w - 1; c >= 0; --c) next_void[c] = grid.is_hole(c, r) ? c : next_void[std::size_t(c) + 1];
        for (int c = 0; c < w; ++c) {
            if (grid.is_hole(c, r)) last_void = c;
            rows_dilated[grid.index(c, r)] = (c - last_void <= reach || next_void[c] - c <= reach) ? 1 : 0;
        }
    }
    has_voids_ = std::any_of(grid.z.begin(), grid.z.end(), [](float v) { return std::isnan(v); });
    near_void_.assign(texels(), 0);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            if (!rows_dilated[grid.index(c, r)]) continue;
            for (int y = std::max(0, r - reach); y <= std::min(h - 1, r + reach); ++y) near_void_[grid.index(c, y)] = 1;
        }
    // The highest valid height within the near field's reach of each texel (the march's early
    // exit), a separable running maximum over a (2 reach + 1)^2 box.
    std::vector<float> row_top(texels());
    constexpr float kLow = -std::numeric_limits<float>::infinity();
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            float m = kLow;
            for (int x = std::max(0, c - reach); x <= std::min(w - 1, c + reach); ++x) {
                const float v = grid.at(x, r);
                if (v > m) m = v;  // NaN never compares greater
            }
            row_top[grid.index(c, r)] = m;
        }
    near_top_.assign(texels(), kLow);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            float m = kLow;
            for (int y = std::max(0, r - reach); y <= std::min(h - 1, r + reach); ++y)
                m = std::max(m, row_top[grid.index(c, y)]);
            near_top_[grid.index(c, r)] = m;
        }
    far_.resize(texels());
    g_rows_.resize(std::size_t(h));
    for (int r = 0; r < h; ++r) g_rows_[std::size_t(r)] = metrics_.g(r);
}

std::vector<float> SunShadowSweep::compute(double sun_azimuth_deg, double sun_elevation_deg) {
    std::vector<float> out;
    compute(sun_azimuth_deg, sun_elevation_deg, out);
    return out;
}

void SunShadowSweep::compute(double sun_azimuth_deg, double sun_elevation_deg, std::vector<float>& out,
                             std::vector<float>* horizon_above_sun) {
    if (!std::isfinite(sun_azimuth_deg) || !std::isfinite(sun_elevation_deg) || sun_elevation_deg < -90.0 ||
        sun_elevation_deg > 90.0)
        throw InputError("sun position: azimuth must be finite and elevation within [-90, 90] degrees");
    const int w = grid_.width, h = grid_.height;
    out.resize(texels());

    Frame f;
    const double phi = geo::azimuth_cw_from_north_to_phi(sun_azimuth_deg);
    f.cs = std::cos(phi);
    f.sn = std::sin(phi);
    // Straight up or down has no shadows to speak of; keep tan finite.
    f.tan_e = std::tan(radians(std::clamp(sun_elevation_deg, -89.9, 89.9)));
    f.curv = curvature_factor(options_.curvature);
    f.elevation = radians(sun_elevation_deg);
    f.radius = options_.sun_radius_rad;
    {
        constexpr float kInf = std::numeric_limits<float>::infinity();
        const double lo = f.elevation - f.radius, hi = f.elevation + f.radius;
        f.tan_lo = lo <= -kPi / 2 ? -kInf : float(std::tan(lo));
        f.tan_hi = hi >= kPi / 2 ? kInf : float(std::tan(hi));
        f.march_lo = f.tan_lo, f.march_hi = f.tan_hi;
        if (horizon_above_sun) {
            horizon_above_sun->resize(texels());
            f.horizon_out = horizon_above_sun->data();
            const double band_lo = f.elevation - kSunHorizonBandRad, band_hi = f.elevation + kSunHorizonBandRad;
            f.march_lo = std::min(f.tan_lo, band_lo <= -kPi / 2 ? -kInf : float(std::tan(band_lo)));
            f.march_hi = std::max(f.tan_hi, band_hi >= kPi / 2 ? kInf : float(std::tan(band_hi)));
        }
    }
    // Sample along the axis the line crosses fastest (as ExactAzimuthSweep::plan).
    f.along_columns = std::abs(f.cs) >= std::abs(f.sn) / metrics_.mean_rho();
    f.h = f.along_columns ? metrics_.min_rho() * std::abs(f.cs) : std::abs(f.sn);
    {
        auto invariant = [&](int col, int row) { return col * f.sn + metrics_.g(row) * f.cs; };
        double lo = invariant(0, 0), hi = lo;
        for (double v : {invariant(w - 1, 0), invariant(0, h - 1), invariant(w - 1, h - 1)})
            lo = std::min(lo, v), hi = std::max(hi, v);
        f.n_min = long(std::floor(lo / f.h)) - 1;
        f.n_max = long(std::ceil(hi / f.h)) + 1;
    }
    // Blockers lie towards +phi: east (cs > 0) is towards the last column, north (sn > 0)
    // towards row 0; walk from there so they are behind.
    double ds_max = 0, shift = 0;
    if (f.along_columns) {
        f.outer_count = w;
        f.outer_start = f.cs > 0 ? w - 1 : 0;
        f.outer_step = f.cs > 0 ? -1 : 1;
        for (int r = 0; r < h; ++r) ds_max = std::max(ds_max, metrics_.dx(r) / std::abs(f.cs));
        shift = std::abs(f.sn) / f.h;
    } else {
        f.outer_count = h;
        f.outer_start = f.sn > 0 ? 0 : h - 1;
        f.outer_step = f.sn > 0 ? 1 : -1;
        for (int r = 0; r < h; ++r) {
            ds_max = std::max(ds_max, metrics_.dy(r) / std::abs(f.sn));
            if (r > 0) shift = std::max(shift, (metrics_.g(r) - metrics_.g(r - 1)) * std::abs(f.cs) / f.h);
        }
    }
    f.line_margin = 2 + long(std::ceil(shift));
    // The near field covers near_m_ from the texel centre; the lines take over at most that far
    // out, so no occluder falls between the two (the overlap is harmless: the max is taken).
    f.delay = std::max(1, int(std::floor(near_m_ / ds_max + 1e-9)));

    const int threads = std::clamp(thread_count(options_.threads), 1, std::max(1, std::min(h, 64)));
    if (int(scratch_.size()) < threads) scratch_.resize(std::size_t(threads));
    const long lines = f.n_max - f.n_min + 1;
    std::barrier sync(threads);
    // Blocks of rows handed out as threads come for them: the march's cost follows the terrain
    // (and the shadows), and a frame written beside the sweep (relight's writer thread) takes
    // part of one core, so fixed shares would wait for the slowest thread.
    constexpr int kRowBlock = 16;
    // The far field likewise, in bands of lines (each band sweeps one line of its neighbour's
    // again, so not too many of them).
    const int line_bands = threads == 1 ? 1 : int(std::min<long>(4L * threads, std::max(1L, lines / 64)));
    std::atomic<int> next_band{0}, next_block{0};
    auto job = [&](int t) {
        for (int b = next_band.fetch_add(1); b < line_bands; b = next_band.fetch_add(1))
            far_field(f, f.n_min + lines * b / line_bands, f.n_min + lines * (b + 1) / line_bands, t);
        sync.arrive_and_wait();
        for (int r0 = kRowBlock * next_block.fetch_add(1); r0 < h; r0 = kRowBlock * next_block.fetch_add(1))
            near_field_rows(f, r0, std::min(h, r0 + kRowBlock), out.data());
    };
    {
        std::vector<std::jthread> pool;
        pool.reserve(std::size_t(threads - 1));
        for (int t = 1; t < threads; ++t) pool.emplace_back(job, t);
        job(0);
    }
}

// Stage 1 for lines [n_begin, n_end) (line n_end is swept too, as the upper neighbour of the
// last texels): far-field horizon tangents into far_ for the texels between them.
TS_SUN_CLONES void SunShadowSweep::far_field(const Frame& f, long n_begin, long n_end, int worker) {
    const int w = grid_.width, h = grid_.height;
    const int lateral = f.along_columns ? h : w;
    const long count = n_end - n_begin + 1;
    if (count <= 0) return;
    LineScratch& s = scratch_[std::size_t(worker)];
    s.shadow.assign(std::size_t(count), kNoShadow);
    s.dist.assign(std::size_t(count), 0.0f);
    s.tangent.assign(std::size_t(count), kNaN);
    s.start.assign(std::size_t(count), -1);
    s.ring.assign(std::size_t(count) * std::size_t(f.delay), kNaN);
    s.step_m.resize(std::size_t(lateral));
    s.sample_z.resize(std::size_t(count));
    s.sample_ds.resize(std::size_t(count));
    if (f.along_columns)  // one column's step along a line through row r, in metres
        for (int r = 0; r < h; ++r) s.step_m[std::size_t(r)] = float(metrics_.dx(r) / std::abs(f.cs));
    float* shadow = s.shadow.data();
    float* dist = s.dist.data();
    float* tangent = s.tangent.data();
    int* start = s.start.data();
    float* ring = s.ring.data();  // [slot * count + line]: the last `delay` samples per line
    float* zs = s.sample_z.data();
    float* dsv = s.sample_ds.data();
    const float tan_e = float(f.tan_e), curv = float(f.curv);
    const double gmax = metrics_.g_max();
    // Fractional lateral index (row or column) of line number u at outer index o: column
    // sweeps go through G (row_at_g_ tabulates RowMetrics::row_of_g), row sweeps are linear.
    const double inv_g_step = 1.0 / g_step_;
    auto row_of_g = [&](double gv) {
        const double x = std::clamp(gv, 0.0, gmax) * inv_g_step;
        const std::size_t k = std::min(std::size_t(x), row_at_g_.size() - 2);
        return row_at_g_[k] + (x - double(k)) * (row_at_g_[k + 1] - row_at_g_[k]);
    };
    auto lateral_of = [&](int o, double u) {
        return f.along_columns ? row_of_g((u * f.h - o * f.sn) / f.cs) : (u * f.h - metrics_.g(o) * f.cs) / f.sn;
    };
    const float* z = grid_.z.data();
    const int delay = f.delay;
    int slot = 0;  // k % delay
    for (int k = 0; k < f.outer_count; ++k, slot = slot + 1 == delay ? 0 : slot + 1) {
        const int o = f.outer_start + k * f.outer_step;
        const int next_slot = slot + 1 == delay ? 0 : slot + 1;
        const float* lat = f.along_columns ? transposed_.data() + std::size_t(o) * h : z + std::size_t(o) * w;
        const float ds_row = f.along_columns || k == 0
                                 ? 0.0f
                                 : float(0.5 * (metrics_.dy(o) + metrics_.dy(o - f.outer_step)) / std::abs(f.sn));
        // Line n lies at lateral index base + n * per_line (in G for column sweeps).
        const double base = f.along_columns ? -o * f.sn / f.cs : -metrics_.g(o) * f.cs / f.sn;
        const double per_line = f.along_columns ? f.h / f.cs : f.h / f.sn;
        const double top = f.along_columns ? gmax : double(w - 1);
        // Lines that meet this column or row; the few beside them have just left (or not yet
        // entered) the grid and are reset.
        const double ua = (0 - base) / per_line, ub = (top - base) / per_line;
        const long n_in_lo = long(std::ceil(std::min(ua, ub) - 1e-6)), n_in_hi = long(std::floor(std::max(ua, ub) + 1e-6));
        const long j_lo = std::max(n_in_lo, n_begin) - n_begin, j_hi = std::min(n_in_hi, n_end) - n_begin;
        for (long j = std::max(0L, std::min(j_lo, count) - f.line_margin); j < std::min(j_lo, count); ++j)
            start[j] = -1, shadow[j] = kNoShadow, tangent[j] = kNaN;
        for (long j = std::max(0L, j_hi + 1); j < std::min(count, j_hi + 1 + f.line_margin); ++j)
            start[j] = -1, shadow[j] = kNoShadow, tangent[j] = kNaN;
        // One step of every line that meets this column or row, in two passes: the line
        // samples' heights (and steps) gathered from the column or row, then the shadow-height
        // recursion over contiguous arrays, which vectorises. Templated so the common cases (no
        // voids in the grid; row or column sweep) carry no tests they do not need.
        const long jb = std::max(0L, j_lo), je = j_hi + 1;
        const LineGather g{base, per_line, top, n_begin, row_at_g_.data(), int(row_at_g_.size()) - 2, inv_g_step,
                           gmax, lateral, lat, s.step_m.data()};
        if (lateral < 2) {  // one row or column: every line sits on it
            std::fill(zs + jb, zs + std::max(jb, je), lat[0]);
            std::fill(dsv + jb, dsv + std::max(jb, je), f.along_columns ? s.step_m[0] : ds_row);
        } else if (has_voids_)
            f.along_columns ? gather_lines<true, true>(g, jb, je, zs, dsv) : gather_lines<true, false>(g, jb, je, zs, dsv);
        else
            f.along_columns ? gather_lines<false, true>(g, jb, je, zs, dsv)
                            : gather_lines<false, false>(g, jb, je, zs, dsv);
        if (!f.along_columns && lateral >= 2) std::fill(dsv + jb, dsv + std::max(jb, je), ds_row);
        float* __restrict queued_v = ring + std::size_t(slot) * std::size_t(count);  // `delay` steps back
        const float* __restrict next_v = delay == 1 ? zs : ring + std::size_t(next_slot) * std::size_t(count);
        if (has_voids_)
            advance_lines<true>(jb, je, k, delay, tan_e, curv, zs, dsv, queued_v, next_v, shadow, dist, tangent, start);
        else
            advance_lines<false>(jb, je, k, delay, tan_e, curv, zs, dsv, queued_v, next_v, shadow, dist, tangent, start);
        // Texels of this column or row whose lower line is ours: tent-weighted mean of the two
        // lines' tangents (lines without a far field or on a void do not count).
        const double ia = lateral_of(o, double(n_begin)), ib = lateral_of(o, double(n_end));
        const int i_lo = std::max(0, int(std::floor(std::min(ia, ib))) - 1);
        const int i_hi = std::min(lateral - 1, int(std::ceil(std::max(ia, ib))) + 1);
        // Column sweeps keep far_ transposed ([col * h + row]) so that a column's texels are
        // contiguous here (near_field_rows reads it back per row).
        const TentLines t{o * f.sn, f.along_columns ? 0.0 : metrics_.g(o) * f.cs, f.sn, f.cs, f.h, g_rows_.data(),
                          n_begin, n_end, tangent, far_.data() + std::size_t(o) * std::size_t(lateral)};
        if (count >= 2) f.along_columns ? tent_lines<true>(t, i_lo, i_hi) : tent_lines<false>(t, i_lo, i_hi);
    }
}

// Stage 2 for rows [row_begin, row_end): max(far field, exact near-field march) as a tangent
// into out (-infinity: no blocker at all; NaN: void receiver).
TS_SUN_CLONES void SunShadowSweep::near_field_rows(const Frame& f, int row_begin, int row_end, float* out) const {
    const int w = grid_.width, h = grid_.height;
    const float* z = grid_.z.data();
    const double wmax = w - 1, hmax = h - 1;
    std::vector<NearStep> steps;
    std::vector<float> reach(static_cast<std::size_t>(w)), ray_top(static_cast<std::size_t>(w));
    std::vector<int> range_lo, range_hi;  // per row offset of the steps' cells: their corners' column range
    std::vector<float> window(static_cast<std::size_t>(2 * w + 64));  // running maxima of one range
    constexpr float kFar = std::numeric_limits<float>::infinity();
    // The steps (and the corners they read) depend on the row only through its spacing: built
    // again only when that changes (every row on a geographic grid, once on a projected one).
    double built_dx = -1, built_dy = -1;
    int steps_c_lo = 0, steps_c_hi = w - 2, row0_min = 0, row0_max = 0;
    for (int row = row_begin; row < row_end; ++row) {
        const double dx = metrics_.dx(row), dy = metrics_.dy(row), ds = kMarchStepTexels * std::min(dx, dy);
        if (dx != built_dx || dy != built_dy) {
            built_dx = dx, built_dy = dy;
            const double dc = f.cs * ds / dx, dr = -f.sn * ds / dy;
            // Steps of 1/4 texel as the exact path for the first near_field_fine_texels (where
            // the slope from the crease at the texel centre changes fastest), coarser after that.
            const double coarse = options_.near_field_step_texels / kMarchStepTexels * ds;
            const double fine_m = std::min(near_m_, options_.near_field_fine_texels / kMarchStepTexels * ds);
            steps.clear();
            steps_c_lo = 0, steps_c_hi = w - 2;  // columns whose every step's corners are in the grid
            row0_min = 0, row0_max = 0;
            for (double dist = ds; dist <= near_m_ * (1 + 1e-9); dist += dist < fine_m * (1 - 1e-9) ? ds : coarse) {
                NearStep st;
                st.dcol = dist / ds * dc;
                st.drow = dist / ds * dr;
                st.col0 = int(std::floor(st.dcol));
                st.row0 = int(std::floor(st.drow));
                const float fc = float(st.dcol - st.col0), fr = float(st.drow - st.row0);
                st.w00 = (1 - fc) * (1 - fr), st.w10 = fc * (1 - fr), st.w01 = (1 - fc) * fr, st.w11 = fc * fr;
                st.inv_s = float(1.0 / dist);
                st.drop = float(f.curv * dist);
                st.dist = float(dist);
                steps_c_lo = std::max(steps_c_lo, -st.col0);
                steps_c_hi = std::min(steps_c_hi, w - 2 - st.col0);
                row0_min = std::min(row0_min, st.row0);
                row0_max = std::max(row0_max, st.row0);
                steps.push_back(st);
            }
            // The top is the highest corner of any step's cell (a bilinear sample cannot exceed
            // its corners): the same offsets for the whole row. Each row offset's corners form
            // a column range (the ray's cells are contiguous; a gap would only loosen the bound).
            const int span = row0_max - row0_min + 2;
            range_lo.assign(std::size_t(span), std::numeric_limits<int>::max());
            range_hi.assign(std::size_t(span), std::numeric_limits<int>::min());
            for (const NearStep& st : steps)
                for (int up : {0, 1}) {
                    const std::size_t k = std::size_t(st.row0 + up - row0_min);
                    range_lo[k] = std::min(range_lo[k], st.col0);
                    range_hi[k] = std::max(range_hi[k], st.col0 + 1);
                }
        }
        int c_lo = steps_c_lo, c_hi = steps_c_hi;
        const bool rows_fit = h > 1 && row + row0_min >= 0 && row + row0_max + 1 < h;
        const int n_steps = int(steps.size());
        float* best = out + std::size_t(row) * w;
        const float* zr = z + std::size_t(row) * w;
        const std::uint8_t* void_near = near_void_.data() + std::size_t(row) * w;
        if (f.along_columns)  // far_ is [col * h + row] then
            for (int c = 0; c < w; ++c) best[c] = far_[std::size_t(c) * h + row];
        else
            std::copy_n(far_.data() + std::size_t(row) * w, w, best);
        if (!rows_fit || n_steps == 0) c_lo = w, c_hi = -1;  // all scalar (or nothing to march)
        // Vector path: every texel of [c_lo, c_hi] shares each step's offsets and weights.
        // A step at distance s can only matter if even the highest point in the march's reach,
        // (top - z0) / s, beats max(best, tan_lo) (below the disc's lowest point the horizon is
        // irrelevant) and best is not already above the disc: so each texel needs the steps
        // closer than reach[c], and a chunk of texels the steps closer than its largest reach.
        // The march ignores the curvature drop here, which only makes the bound looser.
        float* __restrict top = ray_top.data();
        if (c_lo <= c_hi) std::fill(top + c_lo, top + c_hi + 1, -kFar);
        // Per row offset, the highest of its corner range [a, b] beside each texel: directly for
        // short ranges, else as a running maximum over windows doubled up to the range (van
        // Herk style, log2 of the width in passes instead of the width).
        for (int k = 0; c_lo <= c_hi && k < int(range_lo.size()); ++k) {
            const int a = range_lo[std::size_t(k)], b = range_hi[std::size_t(k)];
            if (a > b) continue;  // no corner on this row offset
            const int len = b - a + 1;
            const float* __restrict p = z + std::size_t(row + row0_min + k) * w + a;
            if (len <= 3) {
                for (int x = 0; x < len; ++x)
                    for (int c = c_lo; c <= c_hi; ++c) top[c] = p[c + x] > top[c] ? p[c + x] : top[c];
                continue;
            }
            const int n = c_hi - c_lo + len;  // window starts c_lo .. c_hi + len - 1
            float* __restrict win = window.data();
            std::copy_n(p + c_lo, n, win);
            int width = 1;
            for (; 2 * width <= len; width *= 2)
                for (int i = 0; i + width < n; ++i) win[i] = win[i + width] > win[i] ? win[i + width] : win[i];
            for (int c = c_lo; c <= c_hi; ++c) {
                const float m = std::max(win[c - c_lo], win[c - c_lo + len - width]);
                top[c] = m > top[c] ? m : top[c];
            }
        }
        for (int c = std::max(c_lo, 0); c <= c_hi; ++c) {
            const float thr = std::max(best[c], f.march_lo), rise = top[c] - zr[c];
            reach[c] = best[c] > f.march_hi ? 0.0f : thr <= 0.0f ? kFar : rise / thr;
        }
        constexpr int kChunk = 32;
        for (int cb = c_lo; cb <= c_hi; cb += kChunk) {
            const int ce = std::min(c_hi + 1, cb + kChunk);
            float need = 0;
            for (int c = cb; c < ce; ++c) need = std::max(need, reach[c]);
            float* __restrict b = best;
            const float* __restrict z0 = zr;
            for (const NearStep& st : steps) {
                if (!(st.dist < need)) break;
                const float* __restrict p = z + std::size_t(row + st.row0) * w + st.col0;
                const float w00 = st.w00, w10 = st.w10, w01 = st.w01, w11 = st.w11, inv_s = st.inv_s, drop = st.drop;
TS_LOOP_IVDEP
                for (int c = cb; c < ce; ++c) {
                    const float zs = w00 * p[c] + w10 * p[c + 1] + w01 * p[c + w] + w11 * p[c + w + 1];
                    const float v = (zs - z0[c]) * inv_s - drop;
                    b[c] = v > b[c] ? v : b[c];
                }
            }
        }
        // Scalar path: texels near a void or the grid's edge, as the exact path marches them
        // (without voids in the grid, only the edges outside [c_lo, c_hi]).
        for (int c = 0; c < w; ++c) {
            if (!has_voids_ && c == c_lo && c_hi >= c_lo) c = c_hi + 1;
            if (c >= w) break;
            const float z0 = zr[c];
            if (std::isnan(z0)) {
                best[c] = kNaN;
                continue;
            }
            if (c >= c_lo && c <= c_hi && !void_near[c]) continue;
            if (c >= c_lo && c <= c_hi)  // redo: voids were read
                best[c] = far_[f.along_columns ? std::size_t(c) * h + row : std::size_t(row) * w + c];
            double b = best[c];
            const float thr = std::max(float(b), f.march_lo), rise = near_top_[std::size_t(row) * w + c] - z0;
            const float need = b > f.march_hi ? 0.0f : thr <= 0.0f ? kFar : rise / thr;
            for (const NearStep& st : steps) {
                if (!(st.dist < need)) break;
                const double cc = c + st.dcol, rr = row + st.drow;
                if (cc < -1e-7 || rr < -1e-7 || cc > wmax + 1e-7 || rr > hmax + 1e-7) break;
                const int c0 = c + st.col0, r0 = row + st.row0;
                float zs = kNoHeight;
                if (c0 >= 0 && r0 >= 0 && c0 + 1 < w && r0 + 1 < h) {
                    const float* p = z + std::size_t(r0) * w + c0;
                    zs = st.w00 * p[0] + st.w10 * p[1] + st.w01 * p[w] + st.w11 * p[w + 1];
                }
                if (std::isnan(zs))
                    zs = bilinear_valid(z, w, h, std::clamp(cc, 0.0, wmax), std::clamp(rr, 0.0, hmax));
                if (!std::isnan(zs)) b = std::max(b, (double(zs) - z0) * double(st.inv_s) - double(st.drop));
            }
            best[c] = float(b);
        }
        // The disc's visible fraction above that horizon; NaN (void) stays NaN. Branch-free
        // (vectorised) for the texels seeing all or none of the disc; those whose horizon
        // crosses it (kept in `reach`) follow.
        const float tan_lo = f.tan_lo, tan_hi = f.tan_hi;
        float* __restrict horizon = reach.data();
        for (int c = 0; c < w; ++c) {
            const float v = best[c];
            const float t = v == -kFar ? 0.0f : v;  // no blocker: horizon 0
            horizon[c] = t;
            best[c] = std::isnan(t) ? kNaN : t < tan_lo ? 1.0f : t > tan_hi ? 0.0f : t;
        }
        if (f.horizon_out) {
            float* rel = f.horizon_out + std::size_t(row) * w;
            const double band = kSunHorizonBandRad;
            for (int c = 0; c < w; ++c)
                rel[c] = std::isnan(horizon[c]) ? kNaN
                                                : float(std::clamp(std::atan(double(horizon[c])) - f.elevation, -band, band));
        }
        constexpr int kBlock = 16;  // a vector test per block, the scalar one only where needed
        for (int cb = 0; cb < w; cb += kBlock) {
            const int ce = std::min(w, cb + kBlock);
            int any = 0;
            for (int c = cb; c < ce; ++c) any |= int((horizon[c] >= tan_lo) & (horizon[c] <= tan_hi));
            if (!any) continue;
            for (int c = cb; c < ce; ++c)
                if (horizon[c] >= tan_lo && horizon[c] <= tan_hi)
                    best[c] = float(sun_disc_visible_fraction(std::atan(double(horizon[c])), f.elevation, f.radius));
        }
    }
}

}  // namespace ts::visibility
