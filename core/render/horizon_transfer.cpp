#include "core/render/horizon_transfer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/sh/sh_basis.hpp"
#include "core/util/angles.hpp"
#include "core/util/parallel_for.hpp"
#include "core/visibility/fast_atan.hpp"
#include "core/visibility/small_angle_trig.hpp"

namespace ts::render {

namespace {

constexpr int kMaxHarmonic = 5;                 // l + 2 for l <= 3
constexpr int kFeatures = 2 + 2 * kMaxHarmonic;  // 1, e0, sin(m e0), cos(m e0)
constexpr int kDftPoints = 16;                   // exact for trigonometric degree < 8
constexpr int kBlock = 256;

// Per azimuth and coefficient: the integral from e0 to pi/2 of the part of (n . w) Y_i(w) cos e
// that goes with n's horizontal component along the azimuth (a) and with n_z (b), each as
// weights of the features 1, e0, sin(m e0), cos(m e0) (m = 1..harmonics).
// Made in double, kept in float: the per-texel sums are float.
struct ElevationIntegrals {
    int harmonics = 0, features = 0, coefficients = 0;
    std::vector<float> weight;  // [d][i][2][features]: a's weights, then b's

    std::size_t offset(int d, int i, int part) const {
        return ((std::size_t(d) * coefficients + i) * 2 + part) * features;
    }
    const float* at(int d, int i, int part) const { return weight.data() + offset(d, i, part); }
};

// The features' weights of int_{e0}^{pi/2} g(e) de for g with the given 16-point samples.
void integral_weights(const std::array<double, kDftPoints>& g, int harmonics, double* w) {
    double c0 = 0;
    for (double v : g) c0 += v;
    c0 /= kDftPoints;
    double top = c0 * kPi / 2;  // the antiderivative at pi/2
    w[1] = -c0;
    for (int m = 1; m <= harmonics; ++m) {
        double cm = 0, sm = 0;
        for (int n = 0; n < kDftPoints; ++n) {
            const double e = 2 * kPi * n / kDftPoints;
            cm += g[n] * std::cos(m * e), sm += g[n] * std::sin(m * e);
        }
        cm *= 2.0 / kDftPoints, sm *= 2.0 / kDftPoints;
        // int cos(m e) = sin(m e) / m; int sin(m e) = -cos(m e) / m
        top += cm * std::sin(m * kPi / 2) / m - sm * std::cos(m * kPi / 2) / m;
        w[1 + m] = -cm / m;              // sin(m e0)
        w[1 + harmonics + m] = sm / m;   // cos(m e0)
    }
    w[0] = top;
}

ElevationIntegrals make_table(int directions, int coefficients) {
    ElevationIntegrals t;
    t.coefficients = coefficients;
    t.harmonics = coefficients > 9 ? 5 : 4;
    t.features = 2 + 2 * t.harmonics;
    t.weight.assign(std::size_t(directions) * coefficients * 2 * t.features, 0.0f);
    for (int d = 0; d < directions; ++d) {
        const double phi = visibility::azimuth_rad(d, directions);
        std::array<std::array<double, kDftPoints>, 16> ga{}, gb{};
        for (int n = 0; n < kDftPoints; ++n) {
            const double e = 2 * kPi * n / kDftPoints;
            const glm::dvec3 w(std::cos(e) * std::cos(phi), std::cos(e) * std::sin(phi), std::sin(e));
            const sh::ShVec y = sh::eval(w);  // a polynomial: fine on the whole circle of e
            for (int i = 0; i < coefficients; ++i) {
                ga[i][n] = std::cos(e) * y[i] * std::cos(e);
                gb[i][n] = std::sin(e) * y[i] * std::cos(e);
            }
        }
        for (int i = 0; i < coefficients; ++i)
            for (int part = 0; part < 2; ++part) {
                double w[kFeatures];
                integral_weights(part == 0 ? ga[i] : gb[i], t.harmonics, w);
                // A band-l coefficient has harmonics up to l + 2 only, and symmetry zeroes more:
                // exact zeros let the per-texel loop skip them (the DFT leaves them at rounding level).
                for (int k = 0; k < t.features; ++k)
                    t.weight[t.offset(d, i, part) + std::size_t(k)] = std::abs(w[k]) < 1e-12 ? 0.0f : float(w[k]);
            }
    }
    return t;
}

// One block of kBlock texels from t0 (n of them real: the rest repeat a level open texel, so
// every loop has the block's fixed length and vectorises).
void transfer_block(const ElevationIntegrals& table, const visibility::HorizonSet& set, const NormalField& normals,
                    std::size_t t0, int n, float* out) {
    const int k_count = table.coefficients, f_count = table.features, harmonics = table.harmonics;
    const int directions = set.directions;
    const std::size_t texels = set.texels();
    // The per-texel sums in float (the output's precision; 32 azimuths of about 10 terms each,
    // of the transfer's own size): twice the lanes of double.
    alignas(64) float acc[16][kBlock];
    alignas(64) float fa[kFeatures][kBlock], fb[kFeatures][kBlock];
    alignas(64) float nx[kBlock], ny[kBlock], nz[kBlock], h[kBlock];
    // Per texel at one azimuth: n's horizontal part along it (a), n_z (b), and sin, cos of e0.
    alignas(64) float a_[kBlock], s1[kBlock], c1[kBlock], sm[kBlock], cm[kBlock];
    alignas(64) std::uint8_t void_texel[kBlock];
    for (int j = 0; j < kBlock; ++j) {
        const bool real = j < n;
        const std::size_t t = t0 + std::size_t(real ? j : 0);
        nx[j] = real ? normals.x[t] : 0.0f;
        ny[j] = real ? normals.y[t] : 0.0f;
        nz[j] = real ? std::max(normals.z[t], 1e-6f) : 1.0f;
        void_texel[j] = 0;
    }
    for (int i = 0; i < k_count; ++i) std::fill(acc[i], acc[i] + kBlock, 0.0f);
    // Each loop below is straight-line over the block's texels, so that it vectorises.
    for (int d = 0; d < directions; ++d) {
        const double phi = visibility::azimuth_rad(d, directions);
        const float cphi = float(std::cos(phi)), sphi = float(std::sin(phi));
        const float* horizon = set.plane(d) + t0;
        for (int j = 0; j < n; ++j) h[j] = horizon[j];
        for (int j = n; j < kBlock; ++j) h[j] = 0.0f;
        for (int j = 0; j < kBlock; ++j) {
            const float v = h[j];
            const bool nan = !(v == v);
            void_texel[j] |= std::uint8_t(nan);
            h[j] = nan ? 0.0f : std::min(std::max(v, -1.5707963f), 1.5707963f);
        }
        for (int j = 0; j < kBlock; ++j) {
            const float a = nx[j] * cphi + ny[j] * sphi, b = nz[j];
            // The texel's own plane at this azimuth: a cos e + b sin e = 0.
            const float plane = visibility::fast_atan_lanes(-a / b);
            const float e0 = h[j] > plane ? h[j] : plane;
            // sin e0 and cos e0 from the half angle (|e0 / 2| <= pi / 4; no libm call, which
            // would keep the loop scalar).
            const float half = 0.5f * e0, half2 = half * half;
            const float sh = half * visibility::sin_over_x(half2), ch = visibility::cos_from_square(half2);
            a_[j] = a;
            s1[j] = 2 * sh * ch;
            c1[j] = (ch - sh) * (ch + sh);
            fa[0][j] = a, fb[0][j] = b;
            fa[1][j] = a * e0, fb[1][j] = b * e0;
            sm[j] = s1[j], cm[j] = c1[j];
        }
        // sin(m e0), cos(m e0) by the angle-sum recurrence.
        for (int m = 1; m <= harmonics; ++m) {
            float* fs_a = fa[1 + m];
            float* fs_b = fb[1 + m];
            float* fc_a = fa[1 + harmonics + m];
            float* fc_b = fb[1 + harmonics + m];
            for (int j = 0; j < kBlock; ++j) {
                const float a = a_[j], b = nz[j], s = sm[j], c = cm[j];
                fs_a[j] = a * s, fs_b[j] = b * s;
                fc_a[j] = a * c, fc_b[j] = b * c;
                sm[j] = s * c1[j] + c * s1[j];
                cm[j] = c * c1[j] - s * s1[j];
            }
        }
        for (int i = 0; i < k_count; ++i) {
            const float* wa = table.at(d, i, 0);
            const float* wb = table.at(d, i, 1);
            float* row = acc[i];
            for (int k = 0; k < f_count; ++k) {
                const float ca = wa[k], cb = wb[k];
                const float* xa = fa[k];
                const float* xb = fb[k];
                if (ca != 0 && cb != 0) {
                    for (int j = 0; j < kBlock; ++j) row[j] += ca * xa[j] + cb * xb[j];
                } else if (ca != 0) {
                    for (int j = 0; j < kBlock; ++j) row[j] += ca * xa[j];
                } else if (cb != 0) {
                    for (int j = 0; j < kBlock; ++j) row[j] += cb * xb[j];
                }
            }
        }
    }
    // The trapezoid rule over azimuth (weight 2 pi / D) and the 1 / pi of the transfer.
    const float scale = 2.0f / float(directions);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < n; ++j)
            out[std::size_t(i) * texels + t0 + std::size_t(j)] =
                void_texel[j] ? nan : i < k_count ? acc[i][j] * scale : 0.0f;
}

}  // namespace

void horizon_transfer(const HorizonTransferInputs& in, float* out) {
    if (!in.horizons || !in.normals || !out) throw std::invalid_argument("horizon_transfer: missing inputs");
    const visibility::HorizonSet& set = *in.horizons;
    if (set.directions < 4) throw std::invalid_argument("horizon_transfer: needs 4 or more horizon azimuths");
    if (in.coefficients != 9 && in.coefficients != 16)
        throw std::invalid_argument("horizon_transfer: 9 or 16 coefficients");
    const std::size_t texels = set.texels();
    if (in.normals->x.size() != texels || in.normals->y.size() != texels || in.normals->z.size() != texels)
        throw std::invalid_argument("horizon_transfer: normals and horizons differ in size");
    const ElevationIntegrals table = make_table(set.directions, in.coefficients);
    const long long work_per_row = (long long)set.width * set.directions * in.coefficients * table.features;
    parallel_rows(set.height, in.threads, work_per_row, [&](int r0, int r1) {
        const std::size_t end = std::size_t(r1) * std::size_t(set.width);
        for (std::size_t t = std::size_t(r0) * std::size_t(set.width); t < end; t += kBlock)
            transfer_block(table, set, *in.normals, t, int(std::min<std::size_t>(kBlock, end - t)), out);
    });
}

}  // namespace ts::render
