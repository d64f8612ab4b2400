// DiffuseShading (FrameRenderer's fused per-frame pass) against the formula evaluated in double
// on the same inputs. The tolerance is relative to the size of the terms summed,
// albedo (sum_i |T_i L_i| + vis cos E): fp32 storage within 1e-5 (float rounding), fp16 within
// 1e-3 (each stored T_i and albedo is within 2^-12 relative).
#include <cmath>
#include <random>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/render/diffuse_shading.hpp"

namespace ts::render {
namespace {

// Transfer vectors shaped like the band-corrected diffuse ones (DC ~0.28, higher bands smaller,
// band 3 zero if `nine`), unit normals, albedo, visibility with NaN voids, light with a DC term
// that dominates as a sky's does. An odd texel count exercises the last partial block.
struct Field {
    std::size_t n;
    std::vector<float> t, nx, ny, nz, ar, ag, ab, vis;
    std::array<glm::vec3, 16> light{};
    Field(std::size_t texels, bool nine, unsigned seed) : n(texels) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> u(-1.0f, 1.0f), pos(0.0f, 1.0f);
        t.resize(16 * n);
        for (std::size_t k = 0; k < n; ++k)
            for (int i = 0; i < 16; ++i) {
                const int l = i == 0 ? 0 : i < 4 ? 1 : i < 9 ? 2 : 3;
                const float scale = l == 0 ? 0.28f : l == 1 ? 0.15f : l == 2 ? 0.05f : 0.01f;
                t[std::size_t(i) * n + k] = (l == 3 && nine) ? 0.0f : (l == 0 ? scale * (0.5f + pos(rng)) : scale * u(rng));
            }
        for (std::size_t k = 0; k < n; ++k) {
            glm::vec3 v(u(rng) * 0.6f, u(rng) * 0.6f, 0.3f + pos(rng));
            v /= std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
            nx.push_back(v.x), ny.push_back(v.y), nz.push_back(v.z);
            ar.push_back(0.05f + 0.5f * pos(rng)), ag.push_back(0.05f + 0.5f * pos(rng)), ab.push_back(0.05f + 0.5f * pos(rng));
            vis.push_back(k % 97 == 5 ? NAN : pos(rng) < 0.3f ? 0.0f : pos(rng));
        }
        t[3 * n + 11] = NAN;  // a void texel: NaN in, NaN out
        for (int i = 0; i < 16; ++i) {
            const float s = i == 0 ? 10.0f : 2.0f;
            light[std::size_t(i)] = glm::vec3(s * (i == 0 ? 1.0f : u(rng)), s * (i == 0 ? 1.1f : u(rng)),
                                              s * (i == 0 ? 1.3f : u(rng)));
        }
    }
    DiffuseShading make(int coefficients, DiffuseShading::Precision p) const {
        DiffuseShading::Inputs in;
        in.texels = n;
        in.transfer = t.data();
        in.coefficients = coefficients;
        in.normal[0] = nx.data(), in.normal[1] = ny.data(), in.normal[2] = nz.data();
        in.albedo[0] = ar.data(), in.albedo[1] = ag.data(), in.albedo[2] = ab.data();
        in.precision = p;
        return DiffuseShading(in);
    }
    // The formula in double over all 16 coefficients, and the size of its terms.
    glm::dvec3 reference(std::size_t k, const glm::vec3& s, const glm::vec3& e, glm::dvec3& magnitude) const {
        glm::dvec3 sky(0.0), size(0.0);
        for (int i = 0; i < 16; ++i) {
            const glm::dvec3 term = double(t[std::size_t(i) * n + k]) * glm::dvec3(light[std::size_t(i)]);
            sky += term;
            size += glm::abs(term);
        }
        const double cos_s = std::max(0.0, double(nx[k]) * s.x + double(ny[k]) * s.y + double(nz[k]) * s.z);
        const double v = std::isnan(vis[k]) ? 0.0 : vis[k];
        const glm::dvec3 albedo(ar[k], ag[k], ab[k]);
        magnitude = albedo * (size + v * cos_s * glm::dvec3(e));
        return albedo * (sky + v * cos_s * glm::dvec3(e));
    }
};

void expect_close(const Field& f, const DiffuseShading& d, double rel, int threads) {
    const glm::vec3 s = glm::normalize(glm::vec3(0.3f, -0.5f, 0.4f));
    const glm::vec3 e(30.0f, 28.0f, 25.0f);
    std::vector<glm::vec3> out(f.n, glm::vec3(-1.0f));
    d.shade(f.light, f.vis.data(), s, e, out.data(), threads);
    double worst = 0;
    for (std::size_t k = 0; k < f.n; ++k) {
        glm::dvec3 magnitude;
        const glm::dvec3 want = f.reference(k, s, e, magnitude);
        for (int c = 0; c < 3; ++c) {
            if (k == 11) {
                EXPECT_TRUE(std::isnan(out[k][c])) << k;
                continue;
            }
            const double err = std::abs(out[k][c] - want[c]) / magnitude[c];
            worst = std::max(worst, err);
            ASSERT_LE(err, rel) << "texel " << k << " channel " << c << ": " << out[k][c] << " vs " << want[c];
        }
    }
    ::testing::Test::RecordProperty("worst_relative_error", std::to_string(worst));
}

TEST(DiffuseShading, SingleNineCoefficientsIsFloatRounding) {
    const Field f(1003, true, 1);
    expect_close(f, f.make(9, DiffuseShading::Precision::single), 1e-5, 1);
}

TEST(DiffuseShading, SingleSixteenCoefficientsIsFloatRounding) {
    const Field f(1003, false, 2);
    expect_close(f, f.make(16, DiffuseShading::Precision::single), 1e-5, 2);
}

TEST(DiffuseShading, HalfIsWithinOnePerMille) {
    const Field f9(4099, true, 3);
    expect_close(f9, f9.make(9, DiffuseShading::Precision::half), 1e-3, 2);
    const Field f16(777, false, 4);
    expect_close(f16, f16.make(16, DiffuseShading::Precision::half), 1e-3, 1);
}

TEST(DiffuseShading, CompactCopySizes) {
    const Field f(16, true, 5);
    // Per texel: 9 or 16 coefficients + 3 albedo + 3 normal components, 4 bytes each (single) or
    // 2 (half: fp16 and 16-bit fixed point).
    EXPECT_EQ(f.make(9, DiffuseShading::Precision::single).bytes(), 16u * 15 * 4);
    EXPECT_EQ(f.make(16, DiffuseShading::Precision::single).bytes(), 16u * 22 * 4);
    const std::size_t half = f.make(9, DiffuseShading::Precision::half).bytes();
    EXPECT_TRUE(half == 16u * 15 * 2 || half == 16u * 15 * 4) << half;  // fp32 without a compiler fp16 type
}

TEST(DiffuseShading, RejectsBadInputs) {
    DiffuseShading::Inputs in;
    in.texels = 4;
    in.coefficients = 9;
    EXPECT_THROW(DiffuseShading{in}, std::invalid_argument);  // null arrays
    in.coefficients = 10;
    EXPECT_THROW(DiffuseShading{in}, std::invalid_argument);
}

}  // namespace
}  // namespace ts::render
