// The transfer stage (core/render/transfer.hpp) and the exponentiation it shares with the GPU
// (core/sh/sh_exp_shared.h, core/sh/sh_product_shared.h), against core/sh's own tensor, its
// exp_hybrid, and the slow triple-product reference.
#include "core/render/transfer.hpp"
#include "core/util/angles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "core/material/log_brdf.hpp"
#include "core/sh/log_scenes.hpp"
#include "core/sh/sh_exp.hpp"
#include "core/sh/sh_exp_shared.hpp"
#include "core/sh/sh_product.hpp"

namespace ts::render {
namespace {

namespace xs = sh::exp_shared;
constexpr float kNan = std::numeric_limits<float>::quiet_NaN();

// A random unit vector, upper hemisphere when `up` (a terrain normal).
glm::dvec3 random_direction(sh::SplitMix64& rng, bool up) {
    const double z = up ? rng.uniform(0.05, 1.0) : rng.uniform(-1.0, 1.0);
    const double phi = rng.uniform(0.0, 2.0 * kPi);
    const double s = std::sqrt(1.0 - z * z);
    return {s * std::cos(phi), s * std::sin(phi), z};
}

double norm16(const float* v) {
    double s = 0;
    for (int i = 0; i < 16; ++i) s += double(v[i]) * v[i];
    return std::sqrt(s);
}

// Texels with log-visibility from random scenes (height field and blockers, the exponentiation
// study's scenes), random normals and the default diffuse lobe, in the layouts transfer.hpp takes.
struct Texels {
    std::size_t n = 0;
    std::vector<float> log_vis, axis, zh;  // [16][n], [n][3], [n][4]
    std::vector<sh::ShVec> v;              // the log-visibility in double, per texel
};

Texels random_texels(std::size_t n, std::uint64_t seed, double log_eps = -2.302585092994046) {
    sh::SplitMix64 rng(seed);
    const sh::LogBrdfTable table;
    Texels t;
    t.n = n;
    t.log_vis.resize(16 * n);
    t.axis.resize(3 * n);
    t.zh.resize(4 * n);
    for (std::size_t i = 0; i < n; ++i) {
        sh::SceneOptions o;
        o.blockers = int(i % 5) * 4;
        o.height_field = true;
        o.log_eps = log_eps;
        const sh::ShVec v = sh::random_visibility_log(o, rng);
        t.v.push_back(v);
        for (int c = 0; c < 16; ++c) t.log_vis[std::size_t(c) * n + i] = float(v[std::size_t(c)]);
        const glm::dvec3 a = random_direction(rng, true);
        for (int c = 0; c < 3; ++c) t.axis[3 * i + std::size_t(c)] = float(a[c]);
        const sh::ZhVec zh = table.phong(std::exp(rng.uniform(0.0, std::log(100.0))));
        for (int c = 0; c < 4; ++c) t.zh[4 * i + std::size_t(c)] = float(zh[std::size_t(c)]);
    }
    return t;
}

TransferInputs inputs_of(const Texels& t) {
    TransferInputs in;
    in.texels = t.n;
    in.log_visibility = t.log_vis.data();
    in.lobe_axis = t.axis.data();
    in.lobe_log_zh = t.zh.data();
    return in;
}

// --- the shared header against core/sh ---------------------------------------------------------

TEST(ShExpShared, ProductIsTheTriplingTensor) {
    // Every product of two basis vectors is one slice of Gamma_ijk. The generated constants are
    // Gamma rounded to float (relative 6e-8 of values <= 0.29): 1e-7 absolute.
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < 16; ++j) {
            float a[16] = {}, b[16] = {}, c[16];
            a[i] = 1.0f;
            b[j] = 1.0f;
            xs::ts_sh_product(a, b, c);
            for (int k = 0; k < 16; ++k) ASSERT_NEAR(c[k], sh::tripling(i, j, k), 1e-7) << i << " " << j << " " << k;
        }
}

TEST(ShExpShared, SquareIsTheProductWithItself) {
    // Same sums in another grouping: float rounding of ~30 terms of size ~1, 1e-5 relative.
    sh::SplitMix64 rng(5);
    for (int trial = 0; trial < 50; ++trial) {
        float a[16], sq[16], pr[16], ref[16];
        for (float& x : a) x = float(rng.uniform(-2.0, 2.0));
        xs::ts_sh_square(a, sq);
        xs::ts_sh_product(a, a, pr);
        sh::square(a, ref);
        const double scale = norm16(ref);
        for (int k = 0; k < 16; ++k) {
            EXPECT_NEAR(sq[k], ref[k], 1e-5 * scale) << k;
            EXPECT_NEAR(pr[k], ref[k], 1e-5 * scale) << k;
        }
    }
}

TEST(ShExpShared, OptimalLinearCoefficientsAreCoreShs) {
    // The same table and the same float interpolation: bit for bit.
    EXPECT_EQ(xs::kTsLinearTable[TS_LINEAR_ROWS - 1].magnitude, sh::optimal_linear_max_magnitude());
    for (int s = 0; s <= 4000; ++s) {
        const float m = float(s) * 0.01f;
        float ab[2];
        xs::ts_optimal_linear_coeffs(m, ab);
        const sh::LinearCoeffs c = sh::optimal_linear_coeffs(m);
        ASSERT_EQ(ab[0], c.a) << m;
        ASSERT_EQ(ab[1], c.b) << m;
    }
}

TEST(ShExpShared, HybridIsCoreShsExpHybrid) {
    // Same algorithm in float, products summed in another order: after k squarings (up to 8
    // here, non-DC magnitudes to 200) the difference is float rounding amplified by the
    // squarings: measured <= 1.4e-6 of the result's norm up to magnitude 12, 2e-5 at 200.
    // Bound 1e-4 of the norm.
    sh::SplitMix64 rng(11);
    double worst = 0;
    for (double magnitude : {0.0, 0.3, 1.0, 1.7, 4.0, 12.0, 40.0, 200.0})
        for (double dc : {-20.0, -3.0, 0.0, 2.0})
            for (int trial = 0; trial < 8; ++trial) {
                const sh::ShVec shape = sh::random_log_shape(rng);
                float f[16], got[16], ref[16];
                for (int i = 0; i < 16; ++i) f[i] = float(magnitude * shape[std::size_t(i)]);
                f[0] = float(dc);
                xs::ts_sh_exp_hybrid(f, 1.0f, 24, got);
                sh::exp_hybrid(f, ref, 1.0f, 24);
                const double scale = norm16(ref);
                for (int k = 0; k < 16; ++k) {
                    worst = std::max(worst, std::abs(got[k] - ref[k]) / scale);
                    ASSERT_NEAR(got[k], ref[k], 1e-4 * scale) << magnitude << " " << dc << " " << k;
                }
            }
    std::printf("shared hybrid vs sh::exp_hybrid: worst %.2e of the norm\n", worst);
}

TEST(ShExpShared, NonFiniteInputGivesZerosAndHugeInputStaysFinite) {
    sh::SplitMix64 rng(13);
    for (double scale : {1e3, 1e5, 1e20}) {
        const sh::ShVec shape = sh::random_log_shape(rng);
        float f[16], out[16];
        for (int i = 0; i < 16; ++i) f[i] = float(scale * shape[std::size_t(i)]);
        f[0] = 100.0f;
        xs::ts_sh_exp_hybrid(f, 1.0f, 24, out);
        for (float v : out) ASSERT_TRUE(std::isfinite(v)) << scale;
    }
    float f[16] = {};
    float out[16];
    f[5] = std::numeric_limits<float>::infinity();
    xs::ts_sh_exp_hybrid(f, 1.0f, 24, out);
    for (float v : out) EXPECT_EQ(v, 0.0f);
}

// --- transfer_vectors / shade_transfer --------------------------------------------------------

TEST(Transfer, FullyVisibleDiffuseTexelUnderAConstantSkyGivesTheSky) {
    // V_log = 0, the diffuse lobe cos/pi: <T, L> for a constant sky radiance c is c times the
    // lobe's integral, 1 for the true lobe. The exponentiated log lobe (default epsilon) keeps
    // that to ~1% (tests/material/log_brdf_test.cpp: ~1.01), whatever the normal (a rotation keeps the DC).
    // Bound 3%, and all normals must agree with each other to 1e-5 (float rounding only).
    const std::size_t n = 257;
    const sh::LogBrdfTable table;
    const sh::ZhVec d = table.diffuse();
    std::vector<float> v(16 * n, 0.0f), axis(3 * n), zh = {float(d[0]), float(d[1]), float(d[2]), float(d[3])};
    sh::SplitMix64 rng(3);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 a = i == 0 ? glm::dvec3(0, 0, 1) : random_direction(rng, false);
        for (int c = 0; c < 3; ++c) axis[3 * i + std::size_t(c)] = float(a[c]);
    }
    TransferInputs in;
    in.texels = n;
    in.log_visibility = v.data();
    in.lobe_axis = axis.data();
    in.lobe_log_zh = zh.data();
    in.uniform_lobe = true;
    std::vector<float> t(16 * n);
    transfer_vectors(in, t.data());
    std::array<glm::vec3, 16> light{};
    const glm::vec3 sky(0.7f, 1.1f, 2.5f);
    light[0] = sky * float(sh::kSqrt4Pi);  // the constant function `sky`
    std::vector<glm::vec3> rgb(n);
    shade_transfer(t.data(), n, light, rgb.data());
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(rgb[i][c] / sky[c], 1.0, 0.03) << i;
            EXPECT_NEAR(rgb[i][c], rgb[0][c], 1e-5 * rgb[0][c]) << i;
        }
    std::printf("diffuse lobe under a constant sky: %.5f of the sky\n", rgb[0].r / sky.r);
}

TEST(Transfer, UniformLobeEqualsThePerTexelLobe) {
    Texels t = random_texels(3000, 17);
    for (std::size_t i = 0; i < t.n; ++i)
        for (int c = 0; c < 4; ++c) t.zh[4 * i + std::size_t(c)] = t.zh[std::size_t(c)];
    TransferInputs in = inputs_of(t);
    std::vector<float> per_texel(16 * t.n), uniform(16 * t.n);
    transfer_vectors(in, per_texel.data());
    in.uniform_lobe = true;
    in.threads = 1;
    transfer_vectors(in, uniform.data());
    for (std::size_t k = 0; k < per_texel.size(); ++k) ASSERT_EQ(per_texel[k], uniform[k]) << k;
}

TEST(Transfer, MatchesCoreShExpOfTheSummedLog) {
    // The slow path: core/sh's rotation (sh::zh_rotate, double) and sh::sh_exp(hybrid) per
    // texel. Same algorithm in float; 2e-5 of each texel's norm (measured ~2e-6).
    const Texels t = random_texels(500, 19);
    std::vector<float> out(16 * t.n);
    transfer_vectors(inputs_of(t), out.data());
    double worst = 0;
    for (std::size_t i = 0; i < t.n; ++i) {
        const glm::dvec3 a(t.axis[3 * i], t.axis[3 * i + 1], t.axis[3 * i + 2]);
        const sh::ZhVec zh = {t.zh[4 * i], t.zh[4 * i + 1], t.zh[4 * i + 2], t.zh[4 * i + 3]};
        const sh::ShVec lobe = sh::zh_rotate(zh, a);
        float f[16], ref[16];
        for (int c = 0; c < 16; ++c) f[c] = t.log_vis[std::size_t(c) * t.n + i] + float(lobe[std::size_t(c)]);
        sh::sh_exp(sh::ExpMethod::hybrid, f, ref);
        const double scale = norm16(ref);
        for (int c = 0; c < 16; ++c) {
            const double d = std::abs(out[std::size_t(c) * t.n + i] - ref[c]) / scale;
            worst = std::max(worst, d);
            ASSERT_LT(d, 2e-5) << i << " " << c;
        }
    }
    std::printf("transfer vs sh_exp(V + F): worst %.2e of the norm\n", worst);
}

TEST(Transfer, OtherMethodsRunThroughCoreSh) {
    const Texels t = random_texels(64, 23);
    TransferInputs in = inputs_of(t);
    in.method = sh::ExpMethod::scaling_squaring;
    std::vector<float> out(16 * t.n);
    transfer_vectors(in, out.data());
    for (std::size_t i = 0; i < t.n; ++i) {
        const glm::dvec3 a(t.axis[3 * i], t.axis[3 * i + 1], t.axis[3 * i + 2]);
        const sh::ShVec lobe = sh::zh_rotate({t.zh[4 * i], t.zh[4 * i + 1], t.zh[4 * i + 2], t.zh[4 * i + 3]}, a);
        float f[16], ref[16];
        for (int c = 0; c < 16; ++c) f[c] = t.log_vis[std::size_t(c) * t.n + i] + float(lobe[std::size_t(c)]);
        sh::sh_exp(sh::ExpMethod::scaling_squaring, f, ref);
        // The same function on the same inputs except the lobe's rotation (double there, rounded
        // to float here): 1e-5 of the norm.
        for (int c = 0; c < 16; ++c) ASSERT_NEAR(out[std::size_t(c) * t.n + i], ref[c], 1e-5 * norm16(ref));
    }
}

TEST(Transfer, ShadingIsCloseToTheTripleProductReference) {
    // The slides' point: exp(V + F) dotted with L instead of the triple product
    // <exp(V) * exp(F), L> (two exponentials and an SH product per texel and light). Both are
    // order-4 approximations of int V rho L; they differ by the product's band-limit
    // truncation, which for these scenes (eps = 0.1, Phong lobes up to 100) is about 1% of the
    // unshadowed sky response on average and up to 10% for the sharpest lobes (measured: mean
    // 0.8%, worst 9.6%). Bounds: mean 2%, worst 20%.
    const Texels t = random_texels(400, 29);
    std::vector<float> T(16 * t.n);
    transfer_vectors(inputs_of(t), T.data());
    std::array<glm::vec3, 16> light{};
    sh::SplitMix64 rng(31);
    // A sky-like light: bright constant plus a gradient toward one side and some detail.
    light[0] = glm::vec3(3.0f, 3.5f, 4.0f);
    for (int i = 1; i < 16; ++i) light[std::size_t(i)] = glm::vec3(float(rng.uniform(-0.4, 0.4)));
    light[2] = glm::vec3(1.5f);
    std::vector<glm::vec3> rgb(t.n);
    shade_transfer(T.data(), t.n, light, rgb.data());
    double sum = 0, worst = 0;
    for (std::size_t i = 0; i < t.n; ++i) {
        const glm::dvec3 a(t.axis[3 * i], t.axis[3 * i + 1], t.axis[3 * i + 2]);
        const sh::ShVec lobe = sh::zh_rotate({t.zh[4 * i], t.zh[4 * i + 1], t.zh[4 * i + 2], t.zh[4 * i + 3]}, a);
        float fv[16], fl[16], ev[16], el[16];
        for (int c = 0; c < 16; ++c) {
            fv[c] = float(t.v[i][std::size_t(c)]);
            fl[c] = float(lobe[std::size_t(c)]);
        }
        sh::sh_exp(sh::ExpMethod::hybrid, fv, ev);
        sh::sh_exp(sh::ExpMethod::hybrid, fl, el);
        sh::ShVec dv{}, dl{};
        for (int c = 0; c < 16; ++c) dv[std::size_t(c)] = ev[c], dl[std::size_t(c)] = el[c];
        const sh::ShVec tv = sh::product(dv, dl);
        // The unshadowed response to the light's constant part: the scale errors are judged on.
        const double unshadowed = el[0] * double(light[0].r);
        double ref = 0;
        for (int c = 0; c < 16; ++c) ref += tv[std::size_t(c)] * double(light[std::size_t(c)].r);
        const double d = std::abs(rgb[i].r - ref) / unshadowed;
        sum += d;
        worst = std::max(worst, d);
    }
    std::printf("exp(V+F).L vs <exp V * exp F, L>: mean %.4f worst %.4f of the unshadowed response\n",
                sum / double(t.n), worst);
    EXPECT_LT(sum / double(t.n), 0.02);
    EXPECT_LT(worst, 0.20);
}

TEST(Transfer, NanInGivesNanOutAndLeavesNeighboursAlone) {
    Texels t = random_texels(40, 37);
    std::vector<float> clean(16 * t.n);
    transfer_vectors(inputs_of(t), clean.data());
    t.log_vis[7 * t.n + 3] = kNan;  // one coefficient of texel 3: a void receiver
    t.axis[3 * 9 + 1] = kNan;       // texel 9: no normal
    std::vector<float> out(16 * t.n);
    transfer_vectors(inputs_of(t), out.data());
    for (std::size_t i = 0; i < t.n; ++i)
        for (int c = 0; c < 16; ++c) {
            const float v = out[std::size_t(c) * t.n + i];
            if (i == 3 || i == 9) EXPECT_TRUE(std::isnan(v)) << i << " " << c;
            else EXPECT_EQ(v, clean[std::size_t(c) * t.n + i]) << i << " " << c;
        }
    std::array<glm::vec3, 16> light{};
    light[0] = glm::vec3(1.0f);
    light[3] = glm::vec3(0.0f);  // a zero coefficient must not hide the NaN
    std::vector<glm::vec3> rgb(t.n);
    shade_transfer(out.data(), t.n, light, rgb.data());
    for (std::size_t i = 0; i < t.n; ++i)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(std::isnan(rgb[i][c]), i == 3 || i == 9) << i;
}

TEST(Transfer, ShadeIsTheSixteenTermDotOnEveryBlockSize) {
    // Sizes around the shading block (1024) and the thread split: every texel is the 16-term
    // dot in double within float rounding (1e-6 relative to the sum of |terms|).
    sh::SplitMix64 rng(41);
    std::array<glm::vec3, 16> light{};
    for (auto& l : light) l = glm::vec3(float(rng.uniform(-1, 1)), float(rng.uniform(-1, 1)), float(rng.uniform(0, 2)));
    for (std::size_t n : {1u, 7u, 1023u, 1024u, 1025u, 5000u, 140001u}) {
        std::vector<float> T(16 * n);
        for (float& x : T) x = float(rng.uniform(-3, 3));
        std::vector<glm::vec3> rgb(n);
        shade_transfer(T.data(), n, light, rgb.data(), n > 5000 ? 2 : 1);
        for (std::size_t i = 0; i < n; i += (n > 5000 ? 97 : 1))
            for (int c = 0; c < 3; ++c) {
                double s = 0, mag = 0;
                for (int k = 0; k < 16; ++k) {
                    s += double(T[std::size_t(k) * n + i]) * light[std::size_t(k)][c];
                    mag += std::abs(double(T[std::size_t(k) * n + i]) * light[std::size_t(k)][c]);
                }
                ASSERT_NEAR(rgb[i][c], s, 1e-6 * mag + 1e-30) << n << " " << i;
            }
    }
}

TEST(Transfer, NoTexelsIsANoOp) {
    TransferInputs in;
    transfer_vectors(in, nullptr);
    shade_transfer(nullptr, 0, {}, nullptr);
}

}  // namespace
}  // namespace ts::render
