// project_sky_sh: exactness on constants and band-limited skies, agreement with a brute-force
// fine grid on the real models.
#include "core/light/sky_sh.hpp"
#include "core/util/angles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "core/geo/azimuth.hpp"
#include "core/light/overcast_sky.hpp"
#include "core/light/preetham_sky.hpp"
#include "core/sh/sh_basis.hpp"

namespace ts::light {
namespace {

// A sky given by a function, for the tests.
template <class F>
class FunctionSky final : public Sky {
public:
    explicit FunctionSky(F f) : f_(f) {}
    Rgb radiance(const glm::dvec3& d) const override { return f_(d); }
    SunDisc sun() const override { return {}; }
    std::string describe() const override { return "test sky"; }

private:
    F f_;
};
template <class F>
FunctionSky<F> function_sky(F f) {
    return FunctionSky<F>(f);
}

TEST(SkySh, ConstantSkyGivesOnlyDc) {
    const auto sky = function_sky([](const glm::dvec3&) { return Rgb(2.0f, 0.5f, 1.0f); });
    const SkySh s = project_sky_sh(sky);
    // Gauss-Legendre weights sum to 2 pi per hemisphere exactly up to rounding (float output: 1e-6).
    EXPECT_NEAR(s[0].r, 2.0 * sh::kSqrt4Pi, 1e-6 * 2.0 * sh::kSqrt4Pi);
    EXPECT_NEAR(s[0].g, 0.5 * sh::kSqrt4Pi, 1e-6 * sh::kSqrt4Pi);
    EXPECT_NEAR(s[0].b, 1.0 * sh::kSqrt4Pi, 1e-6 * sh::kSqrt4Pi);
    for (int i = 1; i < sh::kCount; ++i) {
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(s[i][c], 0.0, 1e-6) << i;
    }
}

TEST(SkySh, BandLimitedSkyIsReproduced) {
    // Any order-4 function is a polynomial of degree <= 3; the rule is exact for its products
    // with the basis (degree <= 6), so the coefficients come back to float precision (1e-5).
    sh::ShVec f{};
    for (int i = 0; i < sh::kCount; ++i) f[i] = std::sin(1.3 * i + 0.4);
    f[0] = 5.0;  // keep it mostly positive (not required, but sky-like)
    const auto sky = function_sky([&](const glm::dvec3& d) {
        const double v = sh::reconstruct(f, d);
        return Rgb(static_cast<float>(v), static_cast<float>(2.0 * v), static_cast<float>(-v));
    });
    const SkySh s = project_sky_sh(sky);
    for (int i = 0; i < sh::kCount; ++i) {
        EXPECT_NEAR(s[i].r, f[i], 1e-5) << i;
        EXPECT_NEAR(s[i].g, 2.0 * f[i], 2e-5) << i;
        EXPECT_NEAR(s[i].b, -f[i], 1e-5) << i;
    }
    // And reconstruct_sky_sh is its inverse.
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.3, -0.5, 0.7));
    EXPECT_NEAR(reconstruct_sky_sh(s, d).r, sh::reconstruct(f, d), 1e-4);
}

// Brute force: midpoint rule in (theta, phi), n_theta x 2 n_theta cells, horizon on a cell edge.
SkySh brute_force_sh(const Sky& sky, int n_theta) {
    std::array<glm::dvec3, sh::kCount> acc{};
    const int n_phi = 2 * n_theta;
    const double dt = kPi / n_theta;
    const double dp = 2.0 * kPi / n_phi;
    for (int i = 0; i < n_theta; ++i) {
        const double t = (i + 0.5) * dt;
        const double w = std::sin(t) * dt * dp;
        for (int j = 0; j < n_phi; ++j) {
            const double p = (j + 0.5) * dp;
            const glm::dvec3 d(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
            const glm::dvec3 l(sky.radiance(d));
            const sh::ShVec y = sh::eval(d);
            for (int k = 0; k < sh::kCount; ++k) acc[k] += l * (w * y[k]);
        }
    }
    SkySh out{};
    for (int k = 0; k < sh::kCount; ++k) out[k] = Rgb(acc[k]);
    return out;
}

TEST(SkySh, AgreesWithABruteForceGridOnRealSkies) {
    const glm::dvec3 sun =
        geo::enu_direction(geo::azimuth_cw_from_north_to_phi(120.0), radians(25.0));
    const PreethamSky clear(3.0, 0.2, sun);
    const OvercastSky overcast(1.0, 0.2, sun);
    for (const Sky* sky : {static_cast<const Sky*>(&clear), static_cast<const Sky*>(&overcast)}) {
        const SkySh fast = project_sky_sh(*sky);
        const SkySh brute = brute_force_sh(*sky, 1200);
        // The midpoint rule's error is O(h^2) ~ (pi/1200)^2 ~ 7e-6 relative; the default rule
        // is far more accurate, so the two agree to ~1e-5 of the DC term; allow 1e-4.
        for (int i = 0; i < sh::kCount; ++i) {
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(fast[i][c], brute[i][c], 1e-4 * brute[0][c]) << sky->describe() << " i " << i << " c " << c;
            }
        }
    }
}

// project_sky_sh sums each ring of equal z by azimuthal Fourier terms; it must equal the direct
// sum over the same nodes, sum_j w_j L(d_j) Y(d_j), within rounding (1e-6 of the DC term: the
// output is float).
TEST(SkySh, RingSumsEqualTheDirectSumOverTheSameNodes) {
    const glm::dvec3 sun =
        geo::enu_direction(geo::azimuth_cw_from_north_to_phi(200.0), radians(12.0));
    const PreethamSky clear(2.5, 0.3, sun);
    const auto lumpy = function_sky([](const glm::dvec3& d) {
        const double v = 1.0 + 0.5 * d.x - 0.3 * d.y * d.y * d.x + 0.2 * std::sin(5.0 * d.y) + (d.z < 0 ? 0.4 : 0.0);
        return Rgb(float(v), float(2.0 * v), float(0.5 + d.z * d.z));
    });
    for (const Sky* sky : {static_cast<const Sky*>(&clear), static_cast<const Sky*>(&lumpy)})
        for (const HemisphereRule rule : {HemisphereRule{32, 128}, HemisphereRule{7, 9}}) {
            std::array<glm::dvec3, sh::kCount> direct{};
            for_each_sky_node(rule, true, [&](const glm::dvec3& d, double w) {
                const sh::ShVec y = sh::eval(d);
                for (int i = 0; i < sh::kCount; ++i) direct[std::size_t(i)] += glm::dvec3(sky->radiance(d)) * w * y[std::size_t(i)];
            });
            const SkySh rings = project_sky_sh(*sky, rule);
            for (int i = 0; i < sh::kCount; ++i)
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(rings[std::size_t(i)][c], direct[std::size_t(i)][c], 1e-6 * std::abs(direct[0][c]))
                        << sky->describe() << " rule " << rule.n_z << "x" << rule.n_phi << " i " << i << " c " << c;
        }
}

TEST(SkySh, OvercastHasTheClosedFormCoefficients) {
    // L = L_z (1 + 2 z)/3 on z > 0 and G on z < 0: DC = 2 pi Y00 (L_z (1 + 1)/3 ... ) in closed form:
    // integral over the upper hemisphere of (1 + 2 z)/3 = (2 pi + 2 pi)/3 = 4 pi / 3.
    const OvercastSky sky(1.0, 0.2, {0.0, 0.0, 1.0});
    const double lz = sky.zenith_luminance();
    const double ground = 0.2 * 7.0 / 9.0 * lz;
    const double y00 = 1.0 / sh::kSqrt4Pi;
    const double dc = y00 * (lz * 4.0 * kPi / 3.0 + ground * 2.0 * kPi);
    const SkySh s = project_sky_sh(sky);
    EXPECT_NEAR(s[0].g, dc, 1e-5 * dc);
    // The z-band coefficient: Y10 = sqrt(3/4pi) z; integral of z (1+2z)/3 over z>0 is
    // 2 pi (1/2 + 2/3)/3 and of z over z<0 is -pi.
    const double y10 = std::sqrt(3.0 / (4.0 * kPi));
    const double c10 = y10 * (lz * 2.0 * kPi * (0.5 + 2.0 / 3.0) / 3.0 - ground * kPi);
    EXPECT_NEAR(s[sh::index(1, 0)].g, c10, 1e-5 * dc);
}

}  // namespace
}  // namespace ts::light
