// TerrainGatherer::gather_chunk: gather()'s march for the 8 receivers of a chunk at once. They
// take the same steps, so at each step their samples are 8 neighbouring bilinear reads and their
// tests, slopes and weights one vector each; a scalar march spent much of its time on the
// mispredicted "does this sample rise above the last?" branch (docs/rendering.md, "How the
// gather marches").
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/visibility/fast_atan.hpp"
#include "core/visibility/terrain_gather.hpp"
#include "core/visibility/terrain_gather_weights.hpp"

namespace ts::visibility {
namespace {

constexpr int kGatherLanes = TerrainGatherer::kChunkLanes;
// GCC/Clang vector extension: 8 lanes in floats (one AVX register; two SSE registers on the
// baseline clone). Lane-wise results go through arrays (vector elements read one by one made
// GCC keep the vectors on the stack).
using Float8 = float __attribute__((vector_size(32)));
using Int8 = std::int32_t __attribute__((vector_size(32)));

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define TS_GATHER_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define TS_GATHER_CLONES
#endif

// fast_atan without branches, in floats: the same polynomial and reflection.
[[gnu::always_inline]] inline void atan_lanes(Float8& out, const Float8& x) {
    const Float8 ax = x < 0.0f ? -x : x;
    const Int8 big = ax > 1.0f;
    const Float8 one = Float8{} + 1.0f;
    const Float8 inv = one / (big ? ax : one);
    const Float8 p = atan_unit_interval<Float8, float>(big ? inv : ax);
    const Float8 r = big ? 1.5707963f - p : p;
    out = x < 0.0f ? -r : r;
}

// gather_detail::weight_above in lanes.
[[gnu::always_inline]] inline void weight_lanes(Float8& out, const Float8& h, const Float8& tan_h, const Float8& a,
                                                const Float8& nz) {
    const Float8 c2 = 1.0f / (1.0f + tan_h * tan_h);
    out = sky_above<Float8, float>(h, 2.0f * tan_h * c2, c2, a, nz);
}

// sum[q] += w v[q], 8 channels at a time (a plain loop stays scalar: the two may alias).
[[gnu::always_inline]] inline void add_scaled(float* sum, const float* v, float w, std::size_t channels) {
    std::size_t q = 0;
    for (; q + kGatherLanes <= channels; q += kGatherLanes) {
        Float8 s8, v8;
        std::memcpy(&s8, sum + q, sizeof s8);
        std::memcpy(&v8, v + q, sizeof v8);
        s8 += w * v8;
        std::memcpy(sum + q, &s8, sizeof s8);
    }
    for (; q < channels; ++q) sum[q] += w * v[q];
}

[[gnu::always_inline]] inline bool any_lane(const Int8& m) {
    std::uint64_t q[4];
    std::memcpy(q, &m, sizeof q);
    return (q[0] | q[1] | q[2] | q[3]) != 0;
}

}  // namespace

TS_GATHER_CLONES void TerrainGatherer::gather_chunk(int col0, int row, unsigned lanes) {
    const std::size_t channels = seen_.size(), k_count = distances_.size();
    chunk_seen_.assign(channels * kGatherLanes, 0.0f);
    chunk_far_.assign(kGatherLanes, 0.0);
    chunk_steps_.clear();
    const int w = g_.width, h = g_.height;
    const std::size_t plane = in_.horizons->texels(), texels = std::size_t(w) * std::size_t(h);
    const std::size_t t0 = std::size_t(row) * std::size_t(w) + std::size_t(col0);
    const int stride = in_.horizons->directions / sectors_;
    const float* z = g_.z.data();
    const float* values = in_.values.data();
    const float* scale = in_.record_scale.empty() ? nullptr : in_.record_scale.data();

    alignas(32) float nx_a[kGatherLanes] = {}, ny_a[kGatherLanes] = {}, nz_a[kGatherLanes], z0_a[kGatherLanes] = {};
    alignas(32) std::int32_t use_a[kGatherLanes] = {};
    for (int l = 0; l < kGatherLanes; ++l) {
        nz_a[l] = 1;
        if (!(lanes >> l & 1u)) continue;
        const std::size_t t = t0 + std::size_t(l);
        use_a[l] = -1;
        nx_a[l] = in_.normals->x[t], ny_a[l] = in_.normals->y[t];
        nz_a[l] = std::max(in_.normals->z[t], 1e-6f);
        z0_a[l] = g_.z[t];
    }
    Float8 nx, ny, nz, z0;
    Int8 in_use;
    std::memcpy(&nx, nx_a, sizeof nx);
    std::memcpy(&ny, ny_a, sizeof ny);
    std::memcpy(&nz, nz_a, sizeof nz);
    std::memcpy(&z0, z0_a, sizeof z0);
    std::memcpy(&in_use, use_a, sizeof in_use);
    const Int8 lane_index = {0, 1, 2, 3, 4, 5, 6, 7};

    for (int d = 0; d < sectors_; ++d) {
        alignas(32) float hd_a[kGatherLanes] = {};
        for (int l = 0; l < kGatherLanes; ++l)
            if (use_a[l]) hd_a[l] = in_.horizons->angle[std::size_t(d * stride) * plane + t0 + std::size_t(l)];
        Float8 hd;
        std::memcpy(&hd, hd_a, sizeof hd);
        const Float8 a = nx * float(cos_[std::size_t(d)]) + ny * float(sin_[std::size_t(d)]);
        Float8 tan_max = -a / nz;  // the receivers' own planes
        Float8 h_max, f_max;
        atan_lanes(h_max, tan_max);
        // Lanes with terrain above their plane this way (a NaN horizon compares false).
        const Int8 started = in_use & (hd > h_max);
        if (!any_lane(started)) continue;
        weight_lanes(f_max, h_max, tan_max, a, nz);
        Int8 active = started;
        const Float8 reached_at = hd - float(gather_detail::kHorizonReachedRad);
        const Step* st = steps_.data() + std::size_t(d) * k_count;
        for (std::size_t k = 0; k < k_count; ++k, ++st) {
            const int r0 = row + st->cell_row, c = col0 + st->cell_col;
            if (r0 < 0 || r0 + 1 >= h) break;  // every lane left the grid
            // Lanes whose cell is in the grid: once out, a lane stays out (its samples move away).
            active &= (lane_index >= -c) & (lane_index < w - 1 - c);
            if (!any_lane(active)) break;
            // The 8 cells' corners: 9 heights on each of two rows, read whole where they are in the grid.
            float top[kGatherLanes + 1], bottom[kGatherLanes + 1];
            const float* p = z + std::size_t(r0) * std::size_t(w);
            if (c >= 0 && c + kGatherLanes + 1 <= w) {
                std::memcpy(top, p + c, sizeof top);
                std::memcpy(bottom, p + w + c, sizeof bottom);
            } else {
                for (int i = 0; i <= kGatherLanes; ++i) {
                    const int ci = std::clamp(c + i, 0, w - 1);
                    top[i] = p[ci], bottom[i] = p[w + ci];
                }
            }
            Float8 z00, z01, z10, z11;
            std::memcpy(&z00, top, sizeof z00);
            std::memcpy(&z01, top + 1, sizeof z01);
            std::memcpy(&z10, bottom, sizeof z10);
            std::memcpy(&z11, bottom + 1, sizeof z11);
            const Float8 upper = z00 + st->fx * (z01 - z00);
            const Float8 lower = z10 + st->fx * (z11 - z10);
            const Float8 zs = upper + st->fy * (lower - upper);  // NaN next to a void: skipped
            const Float8 tan_s = (zs - z0) * st->inv_dist - st->curvature_drop;
            const Int8 rise = active & (tan_s > tan_max);
            if (!any_lane(rise)) continue;
            Float8 h_s, f_s;
            atan_lanes(h_s, tan_s);
            weight_lanes(f_s, h_s, tan_s, a, nz);
            const Float8 wt = rise ? f_max - f_s : Float8{};  // (0, where tan_s may be NaN)
            tan_max = rise ? tan_s : tan_max;
            h_max = rise ? h_s : h_max;
            f_max = rise ? f_s : f_max;
            // Within reach of the exact horizon nothing further adds more than the far weight's sliver.
            active &= ~(rise & (h_max >= reached_at));
            // The values' texels: neighbours, one per lane (those that rose are in the grid).
            // Without branches per lane (they mispredict): a lane that did not rise adds 0 times
            // its texel's values; one whose texel has none adds 0 times a row of zeros and gives
            // its weight to the far weight.
            alignas(32) float wt_a[kGatherLanes], rec_a[kGatherLanes];
            std::memcpy(wt_a, &wt, sizeof wt_a);
            const long long j0 = (long long)(row + st->near_row) * w + (long long)(col0 + st->near_col);
            bool any_seen = false;
            for (int l = 0; l < kGatherLanes; ++l) {
                const long long j = j0 + l;
                const bool inside = j >= 0 && std::size_t(j) < texels;  // always, for a lane that rose
                const std::size_t at = inside ? std::size_t(j) : 0;
                const float* vs = values + at * channels;
                const bool seen = inside && !std::isnan(vs[0]);
                chunk_far_[std::size_t(l)] += seen ? 0.0f : wt_a[l];
                wt_a[l] = seen ? wt_a[l] : 0.0f;
                any_seen |= wt_a[l] != 0.0f;
                rec_a[l] = scale ? wt_a[l] * (seen ? scale[at] : 0.0f) : wt_a[l];
                add_scaled(chunk_seen_.data() + std::size_t(l) * channels, seen ? vs : zeros_.data(), wt_a[l],
                           channels);
            }
            if (recording_ && any_seen) {
                StepWeights& sw = chunk_steps_.emplace_back();
                sw.step = int(std::size_t(d) * k_count + k);
                std::memcpy(sw.weight, rec_a, sizeof sw.weight);
            }
            if (!any_lane(active)) break;
        }
        alignas(32) float h_a[kGatherLanes], f_a[kGatherLanes], a_a[kGatherLanes];
        alignas(32) std::int32_t started_a[kGatherLanes];
        std::memcpy(h_a, &h_max, sizeof h_a);
        std::memcpy(f_a, &f_max, sizeof f_a);
        std::memcpy(a_a, &a, sizeof a_a);
        std::memcpy(started_a, &started, sizeof started_a);
        for (int l = 0; l < kGatherLanes; ++l)
            if (started_a[l] && hd_a[l] > h_a[l])
                chunk_far_[std::size_t(l)] += f_a[l] - gather_detail::weight_above_horizon(hd_a[l], a_a[l], nz_a[l]);
    }
}

}  // namespace ts::visibility
