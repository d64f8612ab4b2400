// The terrain's diffuse transfer projected exactly from its horizons (core/render/horizon_transfer.hpp):
// closed forms (a level texel, a tilted plane, a ring of equal horizons), a brute-force integral
// over an uneven skyline, void texels, and bad inputs.
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/render/horizon_transfer.hpp"
#include "core/sh/sh_basis.hpp"
#include "core/util/angles.hpp"

namespace ts::render {
namespace {


constexpr int kDirections = 32;

// One texel with horizon h(phi) sampled at D azimuths and normal n.
std::vector<float> transfer_of(const std::function<double(double)>& horizon, const glm::dvec3& n, int coefficients = 9,
                               int directions = kDirections) {
    visibility::HorizonSet set;
    set.width = 1, set.height = 1, set.directions = directions;
    set.angle.resize(std::size_t(directions));
    for (int d = 0; d < directions; ++d) set.angle[std::size_t(d)] = float(horizon(visibility::azimuth_rad(d, directions)));
    NormalField normals;
    normals.x = {float(n.x)}, normals.y = {float(n.y)}, normals.z = {float(n.z)};
    std::vector<float> t(16);
    horizon_transfer({&set, &normals, coefficients, 1}, t.data());
    return t;
}

// The projected clamped cosine / pi about n: the transfer of a texel that sees all of the sky
// over its own plane.
sh::ShVec open_transfer(const glm::dvec3& n) {
    // ZH of max(0, cos) / pi: sqrt(pi)/2, sqrt(pi/3), sqrt(5 pi)/8, 0, each over pi.
    const sh::ZhVec zh = {std::sqrt(kPi) / 2 / kPi, std::sqrt(kPi / 3) / kPi, std::sqrt(5 * kPi) / 8 / kPi, 0.0};
    return sh::zh_rotate(zh, n);
}

// The transfer by brute force, the horizon a continuous function of azimuth.
sh::ShVec brute_force(const std::function<double(double)>& horizon, const glm::dvec3& n) {
    sh::ShVec t{};
    const int az = 1440, el = 1440;
    const double dphi = 2 * kPi / az, de = kPi / el;
    for (int p = 0; p < az; ++p) {
        const double phi = (p + 0.5) * dphi, h = horizon(phi);
        for (int k = 0; k < el; ++k) {
            const double e = -kPi / 2 + (k + 0.5) * de;
            if (e < h) continue;
            const glm::dvec3 w(std::cos(e) * std::cos(phi), std::cos(e) * std::sin(phi), std::sin(e));
            const double c = glm::dot(n, w);
            if (c <= 0) continue;
            const sh::ShVec y = sh::eval(w);
            for (int i = 0; i < 16; ++i) t[std::size_t(i)] += c * y[std::size_t(i)] * std::cos(e) * de * dphi / kPi;
        }
    }
    return t;
}

TEST(HorizonTransfer, ALevelOpenTexelGetsTheProjectedCosine) {
    const sh::ShVec open = open_transfer({0, 0, 1});
    for (double h : {0.0, -0.05}) {  // horizons on its plane, or below it (a peak with curvature)
        const std::vector<float> t = transfer_of([h](double) { return h; }, {0, 0, 1});
        // Below the plane the cosine is zero: the same transfer.
        for (int i = 0; i < 9; ++i) EXPECT_NEAR(t[std::size_t(i)], open[std::size_t(i)], 2e-6) << "h " << h << " i " << i;
        for (int i = 9; i < 16; ++i) EXPECT_EQ(t[std::size_t(i)], 0.0f);
    }
}

TEST(HorizonTransfer, ATiltedPlaneGetsItsProjectedCosine) {
    const glm::dvec3 n = glm::normalize(glm::dvec3(0.4, -0.3, 1.0));
    // The plane's own horizon at every azimuth, and terrain that stays below it.
    const auto plane = [n](double phi) { return std::atan(-(n.x * std::cos(phi) + n.y * std::sin(phi)) / n.z); };
    const sh::ShVec open = open_transfer(n);
    for (const auto& h : {std::function<double(double)>(plane), std::function<double(double)>([](double) { return -1.0; })}) {
        const std::vector<float> t = transfer_of(h, n, 16);
        for (int i = 0; i < 16; ++i) EXPECT_NEAR(t[std::size_t(i)], open[std::size_t(i)], 2e-5) << "i " << i;
    }
}

TEST(HorizonTransfer, ARingOfEqualHorizonsHasItsClosedForm) {
    // Level texel, every horizon at h = 30 degrees: T_lm = 2 int_{sin h}^{1} z Y_l0(z) dz for the
    // zonal terms (Y_00 = 1 / (2 sqrt(pi)), Y_10 = sqrt(3 / 4pi) z, Y_20 = sqrt(5 / 16pi) (3 z^2 - 1));
    // every other term is zero by symmetry.
    const double h = kPi / 6;
    const std::vector<float> t = transfer_of([h](double) { return h; }, {0, 0, 1});
    EXPECT_NEAR(t[0], 0.75 / (2 * std::sqrt(kPi)), 1e-6);
    const double y20 = std::sqrt(5 / (16 * kPi));
    const auto prim = [y20](double z) { return 2 * y20 * (0.75 * z * z * z * z - 0.5 * z * z); };
    EXPECT_NEAR(t[6], prim(1.0) - prim(std::sin(h)), 1e-6);
    EXPECT_NEAR(t[2], 2 * (std::sqrt(3 / (4 * kPi))) * (1 - std::pow(std::sin(h), 3)) / 3, 1e-6);
    for (int i : {1, 3, 4, 5, 7, 8}) EXPECT_NEAR(t[std::size_t(i)], 0.0, 1e-7) << "i " << i;
}

TEST(HorizonTransfer, AnUnevenSkylineOnASlopeMatchesItsIntegral) {
    // A texel on a slope in a valley: high walls across and along, the slope's own plane on its
    // uphill side. The trapezoid rule over 32 azimuths against a fine integral of the continuous
    // skyline: within 1% of T_0 on every coefficient.
    const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, 0.1, 1.0));
    const auto skyline = [n](double phi) {
        const double walls = 0.15 + 0.35 * std::pow(std::cos(phi - 0.4), 2) + 0.1 * std::sin(3 * phi);
        const double plane = std::atan(-(n.x * std::cos(phi) + n.y * std::sin(phi)) / n.z);
        return std::max(walls, plane);
    };
    const std::vector<float> t = transfer_of(skyline, n);
    const sh::ShVec ref = brute_force(skyline, n);
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(t[std::size_t(i)], ref[std::size_t(i)], 0.01 * ref[0]) << "i " << i;
    // And it is below the open texel's: the walls take a sixth of its light.
    EXPECT_LT(t[0], 0.9 * open_transfer(n)[0]);
}

TEST(HorizonTransfer, VoidTexelsGiveNaNAndBadInputsThrow) {
    const std::vector<float> t = transfer_of([](double) { return std::nan(""); }, {0, 0, 1});
    for (float v : t) EXPECT_TRUE(std::isnan(v));
    visibility::HorizonSet set;
    set.width = 2, set.height = 1, set.directions = 8;
    set.angle.resize(16);
    NormalField one;
    one.x = {0}, one.y = {0}, one.z = {1};
    std::vector<float> out(32);
    EXPECT_THROW(horizon_transfer({&set, &one, 9, 1}, out.data()), std::invalid_argument);
    NormalField two;
    two.x = {0, 0}, two.y = {0, 0}, two.z = {1, 1};
    EXPECT_THROW(horizon_transfer({&set, &two, 12, 1}, out.data()), std::invalid_argument);
    set.directions = 2;
    EXPECT_THROW(horizon_transfer({&set, &two, 9, 1}, out.data()), std::invalid_argument);
}

}  // namespace
}  // namespace ts::render
