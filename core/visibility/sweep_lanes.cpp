// The exact sweep's far field, 8 lines at a time as AVX-512 lanes (sweep_lanes.hpp says what
// and why). Each function mirrors a scalar one of exact_horizons.cpp / profile_hull.hpp and
// says which: the operations and their order must stay the same for the sums to stay
// bit-identical. Compiled with -ffp-contract=off (core/visibility/CMakeLists.txt); the target
// below does not enable FMA either.
#include "core/visibility/sweep_lanes.hpp"

#include <immintrin.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#include "core/visibility/surface_sampling.hpp"

namespace ts::visibility {

bool sweep_lanes_supported() {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
           __builtin_cpu_supports("avx512dq");
#else
    return false;
#endif
}

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
// Every function of this part is compiled for AVX-512 (GCC's target pragma; clang applies the
// target attribute to each function).
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx512f,avx512vl,avx512dq"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx512f,avx512vl,avx512dq")
// GCC 12 reports the intrinsics' own _mm*_undefined_* placeholders as maybe-uninitialized.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

namespace {

using namespace sweep_geometry;

constexpr int kLanes = 8;
using VD = __m512d;  // one double per line
using VI = __m256i;  // one int32 per line
using VF = __m256;   // one float per line
using Mask = __mmask8;
constexpr Mask kAll = 0xFF;

#define TS_LANE_INLINE [[gnu::always_inline]] inline

TS_LANE_INLINE VI iota() {
    return _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
}
// Index of entry k of every lane's interleaved array: k * 8 + lane.
TS_LANE_INLINE VI slot(VI k) {
    return _mm256_add_epi32(_mm256_slli_epi32(k, 3), iota());
}
TS_LANE_INLINE VD gather(Mask m, VI index, const double* base) {
    return _mm512_mask_i32gather_pd(_mm512_setzero_pd(), m, index, base, 8);
}
TS_LANE_INLINE VF gather(Mask m, VI index, const float* base) {
    return _mm256_mmask_i32gather_ps(_mm256_set1_ps(std::numeric_limits<float>::quiet_NaN()), m, index, base, 4);
}
TS_LANE_INLINE Mask lt(VI a, VI b) {
    return _mm256_cmpgt_epi32_mask(b, a);
}
TS_LANE_INLINE Mask valid(VF z) {
    return _mm256_cmp_ps_mask(z, z, _CMP_ORD_Q);
}
TS_LANE_INLINE VI inc(VI v, Mask m) {
    return _mm256_mask_add_epi32(v, m, v, _mm256_set1_epi32(1));
}
TS_LANE_INLINE VI dec(VI v, Mask m) {
    return _mm256_mask_sub_epi32(v, m, v, _mm256_set1_epi32(1));
}

// Per-group memory. The hull stacks are per lane, entry k of lane l at k * 8 + l (read by
// gathers, written by scatters). The delayed-insertion queue is one row of 8 lanes per add: every lane adds its
// points in the same order of rows (the rows missing in a lane are masked off), so a lane's
// queue is its entries of the rows in row order, read with plain vector loads. A line has at
// most one sample per column (row) plus 3 blocker points per segment. The queue is a ring of
// queue_rows (a power of 2) rows: a point waits at most until the sweep is `delay` past it.
struct LaneScratch {
    LaneScratch(int points_per_line, long queue_rows)
        : hull_s(new double[std::size_t(points_per_line) * kLanes]),
          hull_u(new double[std::size_t(points_per_line) * kLanes]),
          queue(new QueueRow[std::size_t(queue_rows)]),
          queue_mask(queue_rows - 1) {}
    struct QueueRow {
        VD s, u;
        Mask pending;  // lanes of the row not yet in their hull
    };
    std::unique_ptr<double[]> hull_s, hull_u;
    std::unique_ptr<QueueRow[]> queue;
    long queue_mask;
};

// A point per lane: s along the line and u = z - curvature * s^2.
struct LanePoint {
    VD s, u;
};
TS_LANE_INLINE LanePoint blend(Mask m, LanePoint a, LanePoint b) {
    return {_mm512_mask_mov_pd(a.s, m, b.s), _mm512_mask_mov_pd(a.u, m, b.u)};
}

// DelayedHull + ProfileHull (profile_hull.hpp) for 8 lines.
struct LaneHulls {
    LaneScratch& mem;
    double delay;
    VI count = _mm256_setzero_si256();  // hull vertices per lane
    VI hint = _mm256_setzero_si256();   // last tangent vertex per lane
    // The hull's last three vertices per lane (valid where count >= 1, 2, 3), kept in registers:
    // a pop only shifts them, and the vertex loaded to refill the third is needed only by a
    // second pop, so the load stays off the chain of pop tests.
    LanePoint top{_mm512_setzero_pd(), _mm512_setzero_pd()}, second{_mm512_setzero_pd(), _mm512_setzero_pd()},
        third{_mm512_setzero_pd(), _mm512_setzero_pd()};
    long queue_first = 0, queue_end = 0;  // rows [queue_first, queue_end) may hold pending lanes

    TS_LANE_INLINE LanePoint vertex(Mask m, VI k) const {
        const VI at = slot(k);
        return {gather(m, at, mem.hull_s.get()), gather(m, at, mem.hull_u.get())};
    }

    // DelayedHull::add: (s, u) joins the queue in the lanes of m.
    TS_LANE_INLINE void add(Mask m, VD s, VD u) {
        if (queue_end - queue_first > mem.queue_mask) throw std::logic_error("sweep_lanes: queue ring overflow");
        mem.queue[queue_end++ & mem.queue_mask] = {s, u, m};
    }

    // ProfileHull::insert: pop_hidden, then push.
    TS_LANE_INLINE void insert(Mask m, VD s, VD u) {
        VI n = count;
        const VI two = _mm256_set1_epi32(2), three = _mm256_set1_epi32(3);
        Mask pop = m & _mm256_cmpgt_epi32_mask(n, _mm256_set1_epi32(1));
        while (pop) {
            // a = second, b = top: (a.u - u) * (s - b.s) >= (b.u - u) * (s - a.s)
            const VD lhs = _mm512_mul_pd(_mm512_sub_pd(second.u, u), _mm512_sub_pd(s, top.s));
            const VD rhs = _mm512_mul_pd(_mm512_sub_pd(top.u, u), _mm512_sub_pd(s, second.s));
            pop = _mm512_mask_cmp_pd_mask(pop, lhs, rhs, _CMP_GE_OQ);
            if (!pop) break;
            n = dec(n, pop);
            top = blend(pop, top, second);
            second = blend(pop, second, third);
            if (const Mask refill = pop & _mm256_cmpgt_epi32_mask(n, two))
                third = blend(refill, third, vertex(refill, _mm256_sub_epi32(n, three)));
            pop &= _mm256_cmpgt_epi32_mask(n, _mm256_set1_epi32(1));
        }
        const VI at = slot(n);
        _mm512_mask_i32scatter_pd(mem.hull_s.get(), m, at, s, 8);
        _mm512_mask_i32scatter_pd(mem.hull_u.get(), m, at, u, 8);
        third = blend(m, third, second);
        second = blend(m, second, top);
        top = blend(m, top, LanePoint{s, u});
        count = _mm256_mask_mov_epi32(count, m, inc(n, m));
    }

    // Inserts, in the lanes of m, every queued point at least `delay` behind s: the first half
    // of DelayedHull::query. A lane's queued s only grow, so its ready points come first; lanes
    // that do not query now may drain all the same (the hull depends only on the sequence of
    // points inserted, which stays the lane's queue order).
    TS_LANE_INLINE void drain(Mask m, VD s, Mask gone) {
        const VD reach = _mm512_sub_pd(s, _mm512_set1_pd(delay));
        for (long k = queue_first; k < queue_end; ++k) {
            LaneScratch::QueueRow& row = mem.queue[k & mem.queue_mask];
            const Mask ready = _mm512_mask_cmp_pd_mask(row.pending & m, row.s, reach, _CMP_LE_OQ);
            if (!ready) continue;
            insert(ready, row.s, row.u);
            row.pending &= Mask(~ready);
        }
        while (queue_first < queue_end && !(mem.queue[queue_first & mem.queue_mask].pending & Mask(~gone)))
            ++queue_first;
    }

    // ProfileHull::max_slope_from in the lanes of m; -infinity elsewhere and on empty hulls.
    // Rises(a, b): the slope from (s, u) to b is at least the one to a.
    TS_LANE_INLINE VD max_slope_from(Mask m, VD s, VD u) {
        auto rises = [&](Mask lanes, const LanePoint& a, const LanePoint& b) {
            // (b.u - u) * (s - a.s) >= (a.u - u) * (s - b.s)
            const VD lhs = _mm512_mul_pd(_mm512_sub_pd(b.u, u), _mm512_sub_pd(s, a.s));
            const VD rhs = _mm512_mul_pd(_mm512_sub_pd(a.u, u), _mm512_sub_pd(s, b.s));
            return _mm512_mask_cmp_pd_mask(lanes, lhs, rhs, _CMP_GE_OQ);
        };
        const VI one = _mm256_set1_epi32(1);
        const Mask q = m & _mm256_cmpgt_epi32_mask(count, _mm256_setzero_si256());
        VI i = _mm256_min_epi32(hint, _mm256_sub_epi32(count, one));
        LanePoint at = vertex(q, i);
        for (Mask up = q & lt(_mm256_add_epi32(i, one), count); up;) {
            const LanePoint next = vertex(up, _mm256_add_epi32(i, one));
            up = rises(up, at, next);
            i = inc(i, up);
            at = blend(up, at, next);
            up &= lt(_mm256_add_epi32(i, one), count);
        }
        for (Mask down = q & _mm256_cmpgt_epi32_mask(i, _mm256_setzero_si256()); down;) {
            const LanePoint prev = vertex(down, _mm256_sub_epi32(i, one));
            down &= Mask(~rises(down, prev, at));
            i = dec(i, down);
            at = blend(down, at, prev);
            down &= _mm256_cmpgt_epi32_mask(i, _mm256_setzero_si256());
        }
        hint = _mm256_mask_mov_epi32(hint, q, i);
        // (pts[i].u - u) / (s - pts[i].s)
        const VD slope = _mm512_div_pd(_mm512_sub_pd(at.u, u), _mm512_sub_pd(s, at.s));
        return _mm512_mask_mov_pd(_mm512_set1_pd(-std::numeric_limits<double>::infinity()), q, slope);
    }
};

// The grid and the per-row tables the lanes gather from.
struct LaneGrid {
    const float* z;
    int w, h;
    std::vector<double> g, dx, dy;  // RowMetrics::g, dx and dy per row
    double mean_rho;

    // z[i] and z[i + 1] in the lanes of m (NaN elsewhere), as 8-byte pairs: eight scalar loads,
    // faster overall than a hardware gather on the Zen 4 this was tuned on.
    TS_LANE_INLINE void gather_pairs(Mask m, VI i, VF& first, VF& second) const {
        alignas(32) std::int32_t at[kLanes];
        _mm256_store_si256(reinterpret_cast<__m256i*>(at), _mm256_maskz_mov_epi32(m, i));  // off m: z[0]
        long long v[kLanes];
        for (int l = 0; l < kLanes; ++l) std::memcpy(&v[l], z + at[l], sizeof v[l]);
        const __m512i loaded = _mm512_set_epi64(v[7], v[6], v[5], v[4], v[3], v[2], v[1], v[0]);
        const __m512i pairs = _mm512_mask_mov_epi64(_mm512_set1_epi64(-1), m, loaded);
        first = _mm256_castsi256_ps(_mm512_cvtepi64_epi32(pairs));
        second = _mm256_castsi256_ps(_mm512_cvtepi64_epi32(_mm512_srli_epi64(pairs, 32)));
    }

    // RowMetrics::row_of_g for values in [0, g_max].
    TS_LANE_INLINE VD row_of_g(VD value) const {
        const int last = h - 1;
        const VI one = _mm256_set1_epi32(1);
        VI r = _mm512_cvttpd_epi32(_mm512_div_pd(value, _mm512_set1_pd(mean_rho)));
        r = _mm256_min_epi32(_mm256_max_epi32(r, _mm256_setzero_si256()), _mm256_set1_epi32(last - 1));
        const Mask low = _mm512_cmp_pd_mask(value, _mm512_setzero_pd(), _CMP_LE_OQ);
        const Mask high = _mm512_cmp_pd_mask(value, _mm512_set1_pd(g.back()), _CMP_GE_OQ);
        const Mask inside = Mask(~(low | high));
        for (Mask m = inside & lt(r, _mm256_set1_epi32(last - 1)); m;) {
            m = _mm512_mask_cmp_pd_mask(m, gather(m, _mm256_add_epi32(r, one), g.data()), value, _CMP_LT_OQ);
            r = inc(r, m);
            m &= lt(r, _mm256_set1_epi32(last - 1));
        }
        for (Mask m = inside & _mm256_cmpgt_epi32_mask(r, _mm256_setzero_si256()); m;) {
            m = _mm512_mask_cmp_pd_mask(m, gather(m, r, g.data()), value, _CMP_GT_OQ);
            r = dec(r, m);
            m &= _mm256_cmpgt_epi32_mask(r, _mm256_setzero_si256());
        }
        const VD g0 = gather(inside, r, g.data()), g1 = gather(inside, _mm256_add_epi32(r, one), g.data());
        VD row = _mm512_add_pd(_mm512_cvtepi32_pd(r), _mm512_div_pd(_mm512_sub_pd(value, g0), _mm512_sub_pd(g1, g0)));
        row = _mm512_mask_mov_pd(row, low, _mm512_setzero_pd());
        return _mm512_mask_mov_pd(row, high, _mm512_set1_pd(double(last)));
    }

    TS_LANE_INLINE VD dx_at(VD row) const { return lerp_rows(dx, row); }
    TS_LANE_INLINE VD dy_at(VD row) const { return lerp_rows(dy, row); }

    // RowMetrics::lerp_rows (dx_at, dy_at).
    TS_LANE_INLINE VD lerp_rows(const std::vector<double>& table, VD row) const {
        const double last = double(h - 1);
        const Mask low = _mm512_cmp_pd_mask(row, _mm512_setzero_pd(), _CMP_LE_OQ);
        const Mask high = _mm512_cmp_pd_mask(row, _mm512_set1_pd(last), _CMP_GE_OQ);
        const Mask inside = Mask(~(low | high));
        const VI r0 = _mm512_cvttpd_epi32(row);
        const VD f = _mm512_sub_pd(row, _mm512_cvtepi32_pd(r0));
        const VD v0 = gather(inside, r0, table.data());
        const VD v1 = gather(inside, _mm256_add_epi32(r0, _mm256_set1_epi32(1)), table.data());
        VD v = _mm512_add_pd(v0, _mm512_mul_pd(f, _mm512_sub_pd(v1, v0)));
        v = _mm512_mask_mov_pd(v, low, _mm512_set1_pd(table.front()));
        return _mm512_mask_mov_pd(v, high, _mm512_set1_pd(table.back()));
    }

    // exact_horizons.cpp's surface_at (bilinear_valid) in the lanes of m; NaN elsewhere. Lanes
    // off the common case (a void corner, the last row or column) take the scalar function.
    TS_LANE_INLINE VF surface_at(Mask m, VD col, VD row) const {
        const VI c0 = _mm512_cvttpd_epi32(col), r0 = _mm512_cvttpd_epi32(row);
        const Mask fast = m & lt(_mm256_add_epi32(c0, _mm256_set1_epi32(1)), _mm256_set1_epi32(w)) &
                          lt(_mm256_add_epi32(r0, _mm256_set1_epi32(1)), _mm256_set1_epi32(h));
        const VI i00 = _mm256_add_epi32(_mm256_mullo_epi32(r0, _mm256_set1_epi32(w)), c0);
        const VI i01 = _mm256_add_epi32(i00, _mm256_set1_epi32(w));
        VF z00, z10, z01, z11;
        gather_pairs(fast, i00, z00, z10);
        gather_pairs(fast, i01, z01, z11);
        const Mask ok = fast & valid(z00) & valid(z10) & valid(z01) & valid(z11);
        const VF fc = _mm512_cvtpd_ps(_mm512_sub_pd(col, _mm512_cvtepi32_pd(c0)));
        const VF fr = _mm512_cvtpd_ps(_mm512_sub_pd(row, _mm512_cvtepi32_pd(r0)));
        const VF top = _mm256_add_ps(z00, _mm256_mul_ps(fc, _mm256_sub_ps(z10, z00)));
        const VF bottom = _mm256_add_ps(z01, _mm256_mul_ps(fc, _mm256_sub_ps(z11, z01)));
        VF out = _mm256_add_ps(top, _mm256_mul_ps(fr, _mm256_sub_ps(bottom, top)));
        if (const Mask slow = m & Mask(~ok)) {
            alignas(64) double cs[kLanes], rs[kLanes];
            alignas(32) float zs[kLanes];
            _mm512_store_pd(cs, col);
            _mm512_store_pd(rs, row);
            _mm256_store_ps(zs, out);
            for (int l = 0; l < kLanes; ++l)
                if (slow >> l & 1) zs[l] = bilinear_valid(z, w, h, cs[l], rs[l]);
            out = _mm256_load_ps(zs);
        }
        return out;
    }

    // A line sample's height between texels a and b (index ib valid in has_b):
    // lerp_valid(z[a], z[b], t), or z[a] alone where there is no b.
    TS_LANE_INLINE VF sample(Mask m, VI ia, Mask has_b, VI ib, VF t) const {
        const VF a = gather(m, ia, z), b = gather(m & has_b, ib, z);
        const Mask va = valid(a), vb = valid(b);
        const VF both = _mm256_add_ps(a, _mm256_mul_ps(t, _mm256_sub_ps(b, a)));
        // lerp_valid: both valid -> blend; one valid -> it, if it has weight (1 - t > 1e-6 for
        // a, t > 1e-6 for b); else NaN.
        const VF eps = _mm256_set1_ps(1e-6f);
        const Mask a_weighs = _mm256_cmp_ps_mask(_mm256_sub_ps(_mm256_set1_ps(1.0f), t), eps, _CMP_GT_OQ);
        const Mask b_weighs = _mm256_cmp_ps_mask(t, eps, _CMP_GT_OQ);
        VF out = _mm256_mask_mov_ps(_mm256_set1_ps(std::numeric_limits<float>::quiet_NaN()), va & a_weighs, a);
        out = _mm256_mask_mov_ps(out, vb & Mask(~va) & b_weighs, b);
        out = _mm256_mask_mov_ps(out, va & vb, both);
        return _mm256_mask_mov_ps(a, has_b, out);
    }
};

// One group of 8 lines n0 .. n0 + 7 of an azimuth: the loop of sweep_columns / sweep_rows with
// the lines as lanes. Along = the sampled integer coordinate (col for column sweeps).
class LaneGroup {
public:
    LaneGroup(const SweepSetup& su, const LaneGrid& lg, LaneScratch& mem, bool columns, double cs, double sn, double h)
        : su_(su), lg_(lg), hulls_{mem, su.delay}, columns_(columns), cs_(cs), sn_(sn), h_(h) {}

    void run(long n0, FarFieldSums& acc);

private:
    // add_segment_blockers for the segments (along_a, across_a) -> (along_b, across_b) in m.
    // The along coordinates are consecutive integers, so only the across one can be crossed.
    TS_LANE_INLINE void add_segment_blockers(Mask m, VD s, VD ds, VD along_a, VD across_a, VD along_b, VD across_b);
    TS_LANE_INLINE void splat_lanes(FarFieldSums& acc, Mask m, int along, VD across, VF slope) const;
    TS_LANE_INLINE void add_blocker(Mask m, VD f, VD s, VD ds, VD along_a, VD across_a, VD along_b, VD across_b);

    const SweepSetup& su_;
    const LaneGrid& lg_;
    LaneHulls hulls_;
    bool columns_;
    double cs_, sn_, h_;
};

// sweep_geometry::splat for the lanes of m, the weights and texel indices as vectors, then the
// sums lane by lane in ascending line order: per texel the scalar sweep's order of additions.
void LaneGroup::splat_lanes(FarFieldSums& acc, Mask m, int along, VD across, VF slope) const {
    if (!m) return;
    const ReceiverWindow& win = su_.win;
    // The tent over the local line spacing: column sweeps |cs| / h * rho(row), row sweeps lpt.
    const VD inv_spacing = columns_ ? _mm512_mul_pd(_mm512_set1_pd(std::abs(cs_) / h_),
                                                    _mm512_div_pd(lg_.dy_at(across), lg_.dx_at(across)))
                                    : _mm512_set1_pd(double(su_.lines_per_texel));
    const VD t0 = _mm512_roundscale_pd(across, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
    const VD one = _mm512_set1_pd(1.0);
    alignas(32) std::int32_t index[2][kLanes];
    alignas(32) float weight[2][kLanes], slopes[kLanes];
    Mask use[2];
    for (int k = 0; k < 2; ++k) {
        const VD t = k == 0 ? t0 : _mm512_add_pd(t0, one);
        // w = 1 - |across - t| * inv_spacing, used where w > 0 and the texel is in the window
        const VD dist = _mm512_abs_pd(_mm512_sub_pd(across, t));
        const VD w = _mm512_sub_pd(one, _mm512_mul_pd(dist, inv_spacing));
        const VI ti = _mm512_cvttpd_epi32(t);
        const VI along_i = _mm256_set1_epi32(along);
        const VI lc = _mm256_sub_epi32(columns_ ? along_i : ti, _mm256_set1_epi32(win.col0));
        const VI lr = _mm256_sub_epi32(columns_ ? ti : along_i, _mm256_set1_epi32(win.row0));
        const VI zero = _mm256_setzero_si256();
        use[k] = _mm512_mask_cmp_pd_mask(m, w, _mm512_setzero_pd(), _CMP_GT_OQ) & Mask(~(lt(lc, zero) | lt(lr, zero))) &
                 lt(lc, _mm256_set1_epi32(win.width)) & lt(lr, _mm256_set1_epi32(win.height));
        _mm256_store_si256(reinterpret_cast<__m256i*>(index[k]),
                           _mm256_add_epi32(_mm256_mullo_epi32(lr, _mm256_set1_epi32(win.width)), lc));
        _mm256_store_ps(weight[k], _mm512_cvtpd_ps(w));
    }
    _mm256_store_ps(slopes, slope);
    for (int l = 0; l < kLanes; ++l)
        for (int k = 0; k < 2; ++k)
            if (use[k] >> l & 1) acc.add(std::size_t(std::uint32_t(index[k][l])), weight[k][l], slopes[l]);
}

void LaneGroup::add_blocker(Mask m, VD f, VD s, VD ds, VD along_a, VD across_a, VD along_b, VD across_b) {
    // col_a + f * (col_b - col_a), row_a + f * (row_b - row_a)
    const VD along = _mm512_add_pd(along_a, _mm512_mul_pd(f, _mm512_sub_pd(along_b, along_a)));
    const VD across = _mm512_add_pd(across_a, _mm512_mul_pd(f, _mm512_sub_pd(across_b, across_a)));
    const VF z = columns_ ? lg_.surface_at(m, along, across) : lg_.surface_at(m, across, along);
    const Mask keep = m & valid(z);
    if (!keep) return;
    const VD sp = _mm512_add_pd(s, _mm512_mul_pd(f, ds));
    // double(z) - curvature * (s + f * ds) * (s + f * ds)
    const VD u = _mm512_sub_pd(_mm512_cvtps_pd(z), _mm512_mul_pd(_mm512_mul_pd(_mm512_set1_pd(su_.curvature), sp), sp));
    hulls_.add(keep, sp, u);
}

void LaneGroup::add_segment_blockers(Mask m, VD s, VD ds, VD along_a, VD across_a, VD along_b, VD across_b) {
    // crossing(a, b): the integer k = ceil(min) strictly inside, at fraction f = (k - a) / (b - a).
    const VD lo = _mm512_min_pd(across_a, across_b), hi = _mm512_max_pd(across_a, across_b);
    const VD k = _mm512_roundscale_pd(lo, _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC);
    Mask cut = _mm512_mask_cmp_pd_mask(m, k, lo, _CMP_GT_OQ);
    cut = _mm512_mask_cmp_pd_mask(cut, k, hi, _CMP_LT_OQ);
    const VD f = _mm512_div_pd(_mm512_sub_pd(k, across_a), _mm512_sub_pd(across_b, across_a));
    cut = _mm512_mask_cmp_pd_mask(cut, f, _mm512_set1_pd(kMinCrossing), _CMP_GT_OQ);
    cut = _mm512_mask_cmp_pd_mask(cut, f, _mm512_set1_pd(1 - kMinCrossing), _CMP_LT_OQ);
    // Pieces [0, f], [f, 1] with the cut, else [0, 1]: their midpoints and the cut itself.
    const VD half = _mm512_set1_pd(0.5);
    const VD first_end = _mm512_mask_mov_pd(_mm512_set1_pd(1.0), cut, f);
    add_blocker(m, _mm512_mul_pd(half, _mm512_add_pd(_mm512_setzero_pd(), first_end)), s, ds, along_a, across_a,
                along_b, across_b);
    if (!cut) return;
    add_blocker(cut, f, s, ds, along_a, across_a, along_b, across_b);
    add_blocker(cut, _mm512_mul_pd(half, _mm512_add_pd(f, _mm512_set1_pd(1.0))), s, ds, along_a, across_a, along_b,
                across_b);
}

void LaneGroup::run(long n0, FarFieldSums& acc) {
    const auto& g = su_.grid;
    const double curvature = su_.curvature;
    // Line invariants n * h per lane (the scalar loops' double(n) * h).
    alignas(64) double nh_l[kLanes];
    for (int l = 0; l < kLanes; ++l) nh_l[l] = double(n0 + l) * h_;
    const VD nh = _mm512_load_pd(nh_l);
    const ReceiverWindow& win = su_.win;
    int start, stop, step;
    double across_max, inv_denom;
    if (columns_) {
        step = cs_ > 0 ? -1 : 1;
        start = cs_ > 0 ? g.width - 1 : 0;
        stop = cs_ > 0 ? win.col0 - 1 : win.col0 + win.width;
        across_max = su_.metrics.g_max();
        inv_denom = cs_;
    } else {
        step = sn_ > 0 ? 1 : -1;
        start = sn_ > 0 ? 0 : g.height - 1;
        stop = sn_ > 0 ? win.row0 + win.height : win.row0 - 1;
        across_max = double(g.width - 1);
        inv_denom = sn_;
    }
    const double abs_cs = std::abs(cs_), abs_sn = std::abs(sn_);
    const VD slack_lo = _mm512_set1_pd(-kEdgeSlack), slack_hi = _mm512_set1_pd(across_max + kEdgeSlack);
    const VD two_curv = _mm512_set1_pd(2.0 * curvature), curv = _mm512_set1_pd(curvature);

    VD s = _mm512_setzero_pd(), prev = _mm512_set1_pd(-1.0);
    Mask started = 0, done = 0;
    for (int a = start; a != stop; a += step) {
        // sweep_columns: gv = (n * h - c * sn) / cs; sweep_rows: col = (n * h - G(r) * cs) / sn.
        const double offset = columns_ ? a * sn_ : su_.metrics.g(a) * cs_;
        VD across = _mm512_div_pd(_mm512_sub_pd(nh, _mm512_set1_pd(offset)), _mm512_set1_pd(inv_denom));
        const Mask out =
            _mm512_cmp_pd_mask(across, slack_lo, _CMP_LT_OQ) | _mm512_cmp_pd_mask(across, slack_hi, _CMP_GT_OQ);
        done |= started & out;  // a line that has left the grid
        if (done == kAll) break;
        const Mask act = Mask(~out & ~done);
        if (!act) continue;
        // std::clamp(v, 0, max)
        across = _mm512_mask_mov_pd(across, _mm512_cmp_pd_mask(across, _mm512_setzero_pd(), _CMP_LT_OQ),
                                    _mm512_setzero_pd());
        across = _mm512_mask_mov_pd(across, _mm512_cmp_pd_mask(_mm512_set1_pd(across_max), across, _CMP_LT_OQ),
                                    _mm512_set1_pd(across_max));
        if (columns_) across = lg_.row_of_g(across);  // the row, from G
        const VD along = _mm512_set1_pd(double(a));
        if (const Mask seg = act & started) {
            VD ds;
            if (columns_)  // dx_at(0.5 * (row + prev_row)) / |cs|
                ds = _mm512_div_pd(lg_.dx_at(_mm512_mul_pd(_mm512_set1_pd(0.5), _mm512_add_pd(across, prev))),
                                   _mm512_set1_pd(abs_cs));
            else  // 0.5 * (dy(r) + dy(r - step)) / |sn|
                ds = _mm512_set1_pd(0.5 * (su_.metrics.dy(a) + su_.metrics.dy(a - step)) / abs_sn);
            add_segment_blockers(seg, s, ds, _mm512_set1_pd(double(a - step)), prev, along, across);
            s = _mm512_mask_add_pd(s, seg, s, ds);
        }
        started |= act;
        prev = _mm512_mask_mov_pd(prev, act, across);
        // The sample: between texels (a, t0) and (a, t0 + 1) across.
        const int across_n = columns_ ? g.height : g.width;
        const VI t0 = _mm256_min_epi32(_mm512_cvttpd_epi32(across), _mm256_set1_epi32(across_n - 1));
        const VF frac = _mm512_cvtpd_ps(_mm512_sub_pd(across, _mm512_cvtepi32_pd(t0)));
        const Mask has_b = lt(_mm256_add_epi32(t0, _mm256_set1_epi32(1)), _mm256_set1_epi32(across_n));
        VI ia, ib;
        if (columns_) {
            ia = _mm256_add_epi32(_mm256_mullo_epi32(t0, _mm256_set1_epi32(g.width)), _mm256_set1_epi32(a));
            ib = _mm256_add_epi32(ia, _mm256_set1_epi32(g.width));
        } else {
            ia = _mm256_add_epi32(_mm256_set1_epi32(a * g.width), t0);
            ib = _mm256_add_epi32(ia, _mm256_set1_epi32(1));
        }
        const VF z = lg_.sample(act, ia, has_b, ib, frac);
        const Mask live = act & valid(z);  // inside a void: neither blocks nor receives
        // Every lane on the grid drains its queue each step (also where it does not query
        // now): the queue stays within `delay` of the sweep, and a hull is the same whenever
        // its points are inserted, as long as it is in their order and before its queries.
        hulls_.drain(act, s, done);
        if (!live) continue;
        // far_horizon_at: u = z - curvature * s * s; query; queue the sample itself.
        const VD u = _mm512_sub_pd(_mm512_cvtps_pd(z), _mm512_mul_pd(_mm512_mul_pd(curv, s), s));
        const VD slope = hulls_.max_slope_from(live, s, u);
        hulls_.add(live, s, u);
        // No far field (slope -infinity) stays -infinity here, and is splatted as the scalar
        // sweep splats it (FarFieldSums::add).
        const VF tangent = _mm512_cvtpd_ps(_mm512_sub_pd(slope, _mm512_mul_pd(two_curv, s)));
        splat_lanes(acc, live, a, across, tangent);
    }
}

long sweep_groups(const SweepSetup& su, const SweepPlan& plan, long n_begin, long n_end, FarFieldSums& acc) {
    const auto& g = su.grid;
    LaneGrid lg{g.z.data(), g.width, g.height, {}, {}, {}, su.metrics.mean_rho()};
    lg.g.resize(std::size_t(g.height));
    lg.dx.resize(std::size_t(g.height));
    lg.dy.resize(std::size_t(g.height));
    for (int r = 0; r < g.height; ++r)
        lg.g[std::size_t(r)] = su.metrics.g(r), lg.dx[std::size_t(r)] = su.metrics.dx(r),
        lg.dy[std::size_t(r)] = su.metrics.dy(r);
    // Steps are at least the smallest texel spacing apart along a line (RowMetrics floors dx),
    // so a queued point waits at most delay / spacing + 2 steps of at most 4 points each.
    double spacing = std::numeric_limits<double>::infinity();
    for (int r = 0; r < g.height; ++r) spacing = std::min({spacing, su.metrics.dx(r), su.metrics.dy(r)});
    const double waiting_steps = std::ceil(su.delay / spacing) + 3;
    long queue_rows = 64;
    while (queue_rows < 4 * waiting_steps + 8) queue_rows *= 2;
    LaneScratch mem(4 * (std::max(g.width, g.height) + 2), queue_rows);
    const double cs = std::cos(plan.phi), sn = std::sin(plan.phi);
    const double h = plan.along_columns ? column_line_spacing(su.metrics, su.lines_per_texel, cs)
                                        : row_line_spacing(su.lines_per_texel, sn);
    long n = n_begin;
    for (; n + kLanes <= n_end; n += kLanes) {
        LaneGroup group(su, lg, mem, plan.along_columns, cs, sn, h);
        group.run(n, acc);
    }
    return n;
}

}  // namespace

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC diagnostic pop
#pragma GCC pop_options
#endif
#endif

long sweep_lines_simd(const sweep_geometry::SweepSetup& setup, const SweepPlan& plan, long n_begin, long n_end,
                      FarFieldSums& sums) {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    n_begin = std::max(n_begin, plan.n_min);
    n_end = std::min(n_end, plan.n_max + 1);
    const auto& g = setup.grid;
    // 32-bit lane indices: grid texels and interleaved per-lane entries must fit.
    const std::int64_t texels = std::int64_t(g.width) * g.height;
    const std::int64_t entries = std::int64_t(4) * (std::max(g.width, g.height) + 2) * kLanes;
    if (g.width < 2 || g.height < 2 || texels + g.width + 2 >= std::numeric_limits<std::int32_t>::max() ||
        entries >= std::numeric_limits<std::int32_t>::max() || n_end - n_begin < kLanes || !sweep_lanes_supported())
        return n_begin;
    return sweep_groups(setup, plan, n_begin, n_end, sums);
#else
    (void)setup, (void)plan, (void)n_end, (void)sums;
    return n_begin;
#endif
}

}  // namespace ts::visibility
