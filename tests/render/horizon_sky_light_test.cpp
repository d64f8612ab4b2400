// The sky's light integrated over a texel's horizons (core/render/horizon_sky_light.hpp): a level
// texel under a uniform sky, an uneven skyline and a tilted normal under an anisotropic sky
// against a brute-force integral, agreement with <T, L> where SH is exact (a sky linear in the
// direction), void texels, the sector rule and the sky it takes.
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/light/sky.hpp"
#include "core/render/horizon_sky_light.hpp"
#include "core/render/horizon_transfer.hpp"
#include "core/sh/sh_basis.hpp"
#include "core/util/angles.hpp"

namespace ts::render {
namespace {

constexpr int kSkyTestDirections = 32;

// A sky of radiance a + b . w over the whole sphere (no sun): linear in w, so its SH
// projection (bands 0..1) is exact and <T, L> is the exact integral over the texel's view.
class LinearSky : public light::Sky {
public:
    LinearSky(double a, glm::dvec3 b) : a_(a), b_(b) {}
    light::Rgb radiance(const glm::dvec3& w) const override {
        const double v = a_ + glm::dot(b_, w);
        return light::Rgb(float(v), float(0.5 * v), float(2 * v));
    }
    light::SunDisc sun() const override { return {}; }
    std::string describe() const override { return "linear test sky"; }
    double a_;
    glm::dvec3 b_;
};

struct OneTexel {
    visibility::HorizonSet set;
    NormalField normals;
};

OneTexel texel(const std::function<double(double)>& horizon, glm::dvec3 n, int directions = kSkyTestDirections) {
    OneTexel t;
    t.set.width = 1, t.set.height = 1, t.set.directions = directions;
    t.set.angle.resize(std::size_t(directions));
    for (int d = 0; d < directions; ++d)
        t.set.angle[std::size_t(d)] = float(horizon(visibility::azimuth_rad(d, directions)));
    n = glm::normalize(n);
    t.normals.x = {float(n.x)}, t.normals.y = {float(n.y)}, t.normals.z = {float(n.z)};
    return t;
}

glm::vec3 light_of(const OneTexel& t, const light::Sky& sky, int sectors) {
    SkyLightSettings s;
    s.sectors = sectors;
    const HorizonSkyLight h(t.set, t.normals, s, 1);
    glm::vec3 out;
    h.irradiance_over_pi(sky, &out, 1);
    return out;
}

// E / pi by brute force over the directions above max(horizon(phi), the texel's plane).
glm::dvec3 brute_force(const std::function<double(double)>& horizon, glm::dvec3 n, const light::Sky& sky) {
    n = glm::normalize(n);
    glm::dvec3 e(0.0);
    const int az = 720, el = 720;
    const double dphi = 2 * kPi / az, de = kPi / el;
    for (int p = 0; p < az; ++p) {
        const double phi = (p + 0.5) * dphi, h = horizon(phi);
        for (int k = 0; k < el; ++k) {
            const double el_k = -kPi / 2 + (k + 0.5) * de;
            if (el_k < h) continue;
            const glm::dvec3 w(std::cos(el_k) * std::cos(phi), std::cos(el_k) * std::sin(phi), std::sin(el_k));
            const double c = glm::dot(n, w);
            if (c <= 0) continue;
            e += glm::dvec3(sky.lighting_radiance(w)) * (c * std::cos(el_k) * de * dphi / kPi);
        }
    }
    return e;
}

TEST(HorizonSkyLight, LevelTexelUnderAUniformSkyGetsItsRadiance) {
    const OneTexel t = texel([](double) { return 0.0; }, {0, 0, 1});
    const LinearSky sky(1.0, {0, 0, 0});
    const glm::vec3 e = light_of(t, sky, 16);
    EXPECT_NEAR(e.x, 1.0, 2e-3);
    EXPECT_NEAR(e.y, 0.5, 1e-3);
    EXPECT_NEAR(e.z, 2.0, 4e-3);
}

// Where SH is exact (a sky linear in the direction), the sectors give <T, L> of the projected
// transfer: the same azimuths, units and orientation. An uneven skyline above a tilted plane.
TEST(HorizonSkyLight, EqualsTheTransfersLightForALinearSky) {
    const auto skyline = [](double phi) { return 0.15 + 0.1 * std::sin(2 * phi) + 0.05 * std::cos(3 * phi); };
    for (const glm::dvec3 n : {glm::dvec3(0, 0, 1), glm::dvec3(0.3, -0.2, 1), glm::dvec3(-0.4, 0.1, 1)}) {
        const OneTexel t = texel(skyline, n);
        const LinearSky sky(1.0, {0.6, -0.3, 0.4});  // brighter to the east and up
        std::vector<float> transfer(16);
        horizon_transfer({&t.set, &t.normals, 9, 1}, transfer.data());
        // L's SH: a Y_0 / Y_00 + b . (Y_1,x, Y_1,y, Y_1,z) / c1, c1 = sqrt(3 / (4 pi)).
        const double y00 = 0.5 / std::sqrt(kPi), c1 = std::sqrt(3 / (4 * kPi));
        const double l_sh[4] = {1.0 / y00, -0.3 / c1, 0.4 / c1, 0.6 / c1};  // i = 0, (1,-1)=y, (1,0)=z, (1,1)=x
        double sh_light = 0;
        for (int i = 0; i < 4; ++i) sh_light += transfer[std::size_t(i)] * l_sh[i];
        const glm::vec3 e = light_of(t, sky, 32);
        EXPECT_NEAR(e.x, sh_light, 0.01 * sh_light) << n.x << "," << n.y;
        EXPECT_NEAR(e.z, 2 * sh_light, 0.02 * sh_light);
    }
}

// The physical clear sky, its aureole in the sky, the sun 20 degrees up: what SH cannot hold.
TEST(HorizonSkyLight, MatchesABruteForceIntegralUnderTheClearSky) {
    light::SkyOptions o;
    o.aureole_deg = 0;
    const glm::dvec3 sun = glm::normalize(glm::dvec3(0.66, -0.66, 0.34));
    const auto sky = light::make_sky(o, sun);
    const auto skyline = [](double phi) { return 0.12 + 0.1 * std::sin(phi + 0.5) + 0.04 * std::cos(4 * phi); };
    for (const glm::dvec3 n : {glm::dvec3(0, 0, 1), glm::dvec3(0.5, -0.5, 1), glm::dvec3(-0.5, 0.5, 1)}) {
        const OneTexel t = texel(skyline, n);
        const glm::dvec3 want = brute_force(skyline, n, *sky);
        // One sector per horizon azimuth, the default 16, and 8 (45 degrees: a slope facing the
        // sun reads the aureole's sector at one mean horizon, 3.6% low in red here).
        const glm::vec3 fine = light_of(t, *sky, 32), normal = light_of(t, *sky, 16), coarse = light_of(t, *sky, 8);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(fine[c], want[c], 0.01 * want[c]) << "channel " << c << ", n " << n.x << "," << n.y;
            EXPECT_NEAR(normal[c], want[c], 0.02 * want[c]) << "channel " << c << ", n " << n.x << "," << n.y;
            EXPECT_NEAR(coarse[c], want[c], 0.05 * want[c]) << "channel " << c << ", n " << n.x << "," << n.y;
        }
    }
}

TEST(HorizonSkyLight, VoidTexelsAreNaN) {
    OneTexel t = texel([](double) { return 0.1; }, {0, 0, 1});
    t.set.angle[3] = std::numeric_limits<float>::quiet_NaN();
    const glm::vec3 e = light_of(t, LinearSky(1.0, {0, 0, 0}), 16);
    EXPECT_TRUE(std::isnan(e.x) && std::isnan(e.y) && std::isnan(e.z));
}

TEST(HorizonSkyLight, SectorsAreTheLargestDivisorOfTheDirections) {
    SkyLightSettings s;
    s.sectors = 16;
    EXPECT_EQ(effective_sectors(s, 32), 16);
    EXPECT_EQ(effective_sectors(s, 12), 12);
    EXPECT_EQ(effective_sectors(s, 8), 8);
    s.sectors = 5;
    EXPECT_EQ(effective_sectors(s, 32), 4);
    s.sectors = 1;
    EXPECT_EQ(effective_sectors(s, 7), 1);
}

TEST(HorizonSkyLight, TheSkyKeepsItsAureoleUnlessTheSpecNamesOne) {
    SkyLightSettings horizons, sh;
    sh.mode = SkyLightSettings::Mode::sh;
    light::SkyOptions o;
    EXPECT_EQ(sky_for(o, horizons).aureole_deg, 0.0);
    EXPECT_EQ(sky_for(o, sh).aureole_deg, o.aureole_deg);
    o = light::parse_sky_options("clear:aureole=10");
    EXPECT_EQ(sky_for(o, horizons).aureole_deg, 10.0);
}

}  // namespace
}  // namespace ts::render
