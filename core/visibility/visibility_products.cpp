#include "core/visibility/visibility_products.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/sh/sh_basis.hpp"
#include "core/sh/sh_shared.hpp"
#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "core/util/quantity_error.hpp"
#include "core/util/parallel_for.hpp"
#include "core/visibility/small_angle_trig.hpp"

namespace ts::visibility {

namespace {

constexpr int kCoeffs = 16;
constexpr int kBlock = 64;          // texels computed together: their accumulators stay in L1
constexpr int kBlocksPerItem = 32;  // work item of the thread pool (2048 texels)
// Which of ts_slice_sh_integrals' 10 values coefficient i = l*l + l + m takes: l(l+1)/2 + |m|.
constexpr int kIntegral[kCoeffs] = {0, 2, 1, 2, 5, 4, 3, 4, 5, 9, 8, 7, 6, 7, 8, 9};

// The loops over a block's texels are compiled for AVX-512, AVX2 and baseline x86-64 and
// picked at load time (as sun_sweep.cpp does), so one binary uses the widest vectors it has.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
#define TS_PRODUCT_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define TS_PRODUCT_CLONES
#endif

// One azimuth's horizons across a block, as the sky wedges need them: clamped at 0 (only the
// upper hemisphere counts), the unclamped magnitude (for the part of a wedge above 0), and the
// sine and cosine of half the clamped angle (from which the wedge's sines come without trig).
struct SkyEnds {
    double clamped[kBlock], magnitude[kBlock], sin_half[kBlock], cos_half[kBlock];
};

// Running sums of one block of texels.
struct BlockSums {
    double log_sh[kCoeffs][kBlock];
    double cos2[kBlock], sin[kBlock];
    double probe[kBlock];  // sum of the horizons: NaN exactly when the receiver is void
    double sin_sigma[kBlock], cos_sigma[kBlock];
    SkyEnds ends[3];  // first azimuth, previous, current
};

// Sine and cosine of every horizon of azimuth plane h (n texels), and its sky ends.
TS_PRODUCT_CLONES
void load_azimuth(const float* __restrict h, int n, BlockSums& b, SkyEnds& end) {
    for (int j = 0; j < n; ++j) {
        const double sigma = h[j];
        b.probe[j] += sigma;
        // Half angles lie in [-pi/4, pi/4], where the polynomials hold.
        const double half = 0.5 * sigma;
        const double half2 = half * half;
        const double sh = half * sin_over_x(half2);
        const double ch = cos_from_square(half2);
        b.sin_sigma[j] = 2.0 * sh * ch;
        b.cos_sigma[j] = (ch - sh) * (ch + sh);
        end.clamped[j] = std::max(sigma, 0.0);
        end.magnitude[j] = std::abs(sigma);
        end.sin_half[j] = std::max(sh, 0.0);
        end.cos_half[j] = sh > 0.0 ? ch : 1.0;
    }
}

// Adds the azimuth's slice to the log-SH sums: ts_hf_add_slice with the weights precomputed.
TS_PRODUCT_CLONES
void add_slice(const float* __restrict h, int n, const double* __restrict weight, double log_eps, BlockSums& b) {
    for (int j = 0; j < n; ++j) {
        double e[10];
        sh::shared::ts_slice_sh_integrals_sc(b.sin_sigma[j], b.cos_sigma[j], double(h[j]), log_eps, e);
#pragma GCC unroll 16
        for (int i = 0; i < kCoeffs; ++i) b.log_sh[i][j] += weight[i] * e[kIntegral[i]];
    }
}

// Adds the wedge from azimuth ends a to b, the sky_shared.h means written without branches:
// the part of the wedge above 0 (fraction p of it) is a ramp from a+ = max(a, 0) to b+, and
// with u = (a+ + b+)/2, v = (b+ - a+)/2 the ramp means are
//   mean cos^2 = 1/2 + cos(2u) sinc(2v) / 2 = 1/2 + (1 - 2 sin^2 u) sinc(v) cos(v) / 2
//   mean sin   = sin(u) sinc(v),
// sin u and cos v from the half-angle sines and cosines of a+ and b+. p = (a+ + b+) / (|a| + |b|)
// (1 on a ramp above 0, 0 below, the crossing's fraction otherwise); below 0 the mean cos^2 is 1.
TS_PRODUCT_CLONES
void add_wedge(const SkyEnds& a, const SkyEnds& b, int n, BlockSums& s) {
    for (int j = 0; j < n; ++j) {
        const double sin_u = a.sin_half[j] * b.cos_half[j] + a.cos_half[j] * b.sin_half[j];
        const double cos_v = a.cos_half[j] * b.cos_half[j] + a.sin_half[j] * b.sin_half[j];
        const double v = 0.5 * (b.clamped[j] - a.clamped[j]);
        const double sinc_v = sin_over_x(v * v);
        // Both ends at 0: no part above 0 and a zero span; the max keeps p at 0 without a branch.
        const double span = std::max(a.magnitude[j] + b.magnitude[j], std::numeric_limits<double>::min());
        const double p = (a.clamped[j] + b.clamped[j]) / span;
        s.cos2[j] += p * (0.5 + 0.5 * (1.0 - 2.0 * sin_u * sin_u) * sinc_v * cos_v) + (1.0 - p);
        s.sin[j] += p * sin_u * sinc_v;
    }
}

// out[j] = offset + scale * sum[j] in float, NaN for void receivers (probe NaN).
TS_PRODUCT_CLONES
void store(const double* __restrict sum, const double* __restrict probe, double scale, double offset, int n,
           float* __restrict out) {
    for (int j = 0; j < n; ++j)
        out[j] = probe[j] == probe[j] ? float(offset + scale * sum[j]) : std::numeric_limits<float>::quiet_NaN();
}

// The D x 16 table of ts_slice_azimuth_weight (the azimuthal part of every coefficient).
std::vector<double> azimuth_weights(int directions) {
    std::vector<double> w(std::size_t(directions) * kCoeffs);
    const double delta = 2.0 * kPi / directions;
    for (int d = 0; d < directions; ++d)
        for (int i = 0; i < kCoeffs; ++i)
            w[std::size_t(d) * kCoeffs + i] =
                sh::shared::ts_slice_azimuth_weight(sh::order_of(i), azimuth_rad(d, directions), delta);
    return w;
}

void compute_block(const HorizonSet& set, std::size_t t0, int n, const ProductRequest& r,
                   const std::vector<double>& weights, BlockSums& b, const ProductOutputs& out) {
    const int D = set.directions;
    const bool sky = r.svf || r.sky_visible;
    for (int j = 0; j < n; ++j) b.probe[j] = b.cos2[j] = b.sin[j] = 0.0;
    for (int i = 0; i < kCoeffs; ++i)
        for (int j = 0; j < n; ++j) b.log_sh[i][j] = 0.0;
    SkyEnds* first = &b.ends[0];
    SkyEnds* prev = &b.ends[1];
    SkyEnds* cur = &b.ends[2];
    for (int d = 0; d < D; ++d) {
        const float* h = set.plane(d) + t0;
        SkyEnds* end = d == 0 ? first : cur;
        load_azimuth(h, n, b, *end);
        if (r.log_sh) add_slice(h, n, weights.data() + std::size_t(d) * kCoeffs, r.log_eps, b);
        if (sky && d > 0) add_wedge(d == 1 ? *first : *prev, *cur, n, b);
        if (d > 0) std::swap(prev, cur);
    }
    if (sky) add_wedge(D == 1 ? *first : *prev, *first, n, b);

    if (r.log_sh)
        for (int i = 0; i < kCoeffs; ++i)
            store(b.log_sh[i], b.probe, 1.0, 0.0, n, out.log_sh + std::size_t(i) * set.texels() + t0);
    if (r.svf) store(b.cos2, b.probe, 1.0 / D, 0.0, n, out.svf + t0);
    if (r.sky_visible) store(b.sin, b.probe, -1.0 / D, 1.0, n, out.sky_visible + t0);
}

}  // namespace

VisibilityProducts visibility_products(const HorizonSet& set, const ProductRequest& r) {
    VisibilityProducts out;
    const std::size_t texels = set.texels();
    if (r.log_sh) out.log_sh.resize(texels * kCoeffs);
    if (r.svf) out.svf.resize(texels);
    if (r.sky_visible) out.sky_visible.resize(texels);
    visibility_products_into(set, r, {out.log_sh.data(), out.svf.data(), out.sky_visible.data()});
    return out;
}

void visibility_products_into(const HorizonSet& set, const ProductRequest& r, const ProductOutputs& out) {
    if (r.log_sh && set.directions < 4)
        throw QuantityError(Quantity::sh_output, "", "needs at least 4 directions, got " + std::to_string(set.directions));
    const std::size_t texels = set.texels();
    if (set.directions < 1) {  // no azimuth to average over: as 0 / 0 in the per-texel code
        if (r.svf) std::fill(out.svf, out.svf + texels, std::numeric_limits<float>::quiet_NaN());
        if (r.sky_visible) std::fill(out.sky_visible, out.sky_visible + texels, std::numeric_limits<float>::quiet_NaN());
    }
    if (texels == 0 || set.directions < 1 || !(r.log_sh || r.svf || r.sky_visible)) return;

    const std::vector<double> weights = r.log_sh ? azimuth_weights(set.directions) : std::vector<double>{};
    constexpr std::size_t kItem = std::size_t(kBlock) * kBlocksPerItem;
    const int items = int((texels + kItem - 1) / kItem);
    const int workers = std::min(thread_count(r.threads), items);
    std::vector<BlockSums> scratch(std::size_t(std::max(workers, 1)));
    parallel_for(items, workers, [&](int item, int worker) {
        const std::size_t end = std::min(texels, std::size_t(item + 1) * kItem);
        for (std::size_t t0 = std::size_t(item) * kItem; t0 < end; t0 += kBlock)
            compute_block(set, t0, int(std::min<std::size_t>(kBlock, end - t0)), r, weights,
                          scratch[std::size_t(worker)], out);
    });
}

}  // namespace ts::visibility
