// The ray-traced reference against closed forms: what it integrates must be right before the
// renderer is judged by it (bench render, docs/accuracy.md).
#include "core/render/reference_shading.hpp"
#include "core/util/angles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "core/geo/azimuth.hpp"
#include "core/material/fresnel.hpp"
#include "core/util/error.hpp"
#include "core/visibility/compute_horizons.hpp"
#include "core/visibility/sun_visibility.hpp"

using namespace ts;
using namespace ts::render;

namespace {

// A sky given by a function of the direction, and a sun disc.
class FunctionSky : public light::Sky {
public:
    FunctionSky(std::function<double(const glm::dvec3&)> f, glm::dvec3 sun_dir, double sun_irradiance)
        : f_(std::move(f)), sun_dir_(sun_dir), e_sun_(sun_irradiance) {}
    light::Rgb radiance(const glm::dvec3& dir) const override { return light::Rgb(float(f_(dir))); }
    light::SunDisc sun() const override {
        light::SunDisc d;
        d.direction = sun_dir_;
        d.irradiance = light::Rgb(float(e_sun_));
        return d;
    }
    std::string describe() const override { return "test sky"; }

private:
    std::function<double(const glm::dvec3&)> f_;
    glm::dvec3 sun_dir_;
    double e_sun_;
};

struct ReferenceScene {
    int w, h;
    std::vector<float> z;
    terrain::HeightGrid grid;
    MaterialRaster mat;
    NormalField normals;
    ViewDirections view;  // map: straight up

    ReferenceScene(int w_, int h_, double dx, const std::function<double(double, double)>& f) : w(w_), h(h_) {
        z.resize(std::size_t(w) * h);
        for (int r = 0; r < h; ++r)
            for (int c = 0; c < w; ++c) z[std::size_t(r) * w + c] = float(f((c - w / 2) * dx, (h / 2 - r) * dx));
        grid = terrain::HeightGrid::uniform(w, h, z, dx, dx);
        normals = terrain_normals(grid, 1);
        const std::size_t n = z.size();
        mat.albedo_r.assign(n, 0.2f), mat.albedo_g.assign(n, 0.3f), mat.albedo_b.assign(n, 0.4f);
        mat.ks.assign(n, 0.0f), mat.alpha.assign(n, 1.0f);
        mat.water.assign(n, 0), mat.surface.assign(n, Surface::grassland);
    }
    std::size_t at(int c, int r) const { return std::size_t(r) * w + c; }
};

ReferenceOptions no_curvature() {
    ReferenceOptions o;
    o.curvature = false;
    o.threads = 2;
    return o;
}

SunState sun_at(double az, double el) {
    SunState s;
    s.azimuth_deg = az;
    s.elevation_deg = el;
    return s;
}

}  // namespace

TEST(ReferenceShading, FlatGroundUnderUniformSkyGivesAlbedoAndPhongNormalisation) {
    // Radiance 1 from everywhere, no sun: E = pi (Lambert gives the albedo) and the normalised
    // Phong lobe about the zenith integrates to 1 (adds ks). Smooth integrands on [0, pi/2]:
    // Gauss-Legendre is exact to rounding; results are stored as float: 1e-6 relative.
    ReferenceScene s(21, 21, 30, [](double, double) { return 100.0; });
    const std::size_t t = s.at(10, 10);
    s.mat.ks[t] = 0.1f, s.mat.alpha[t] = 30.0f;
    const ReferenceShader ref(s.grid, s.mat, s.normals, s.view, {t}, no_curvature());
    const FunctionSky sky([](const glm::dvec3&) { return 1.0; }, {0, 0, 1}, 0.0);
    const ReferenceSample out = ref.render(sky, sun_at(180, 90))[0];
    EXPECT_NEAR(out.sky_irradiance.x, kPi, 1e-6 * kPi);
    EXPECT_NEAR(out.radiance.x, 0.2 + 0.1, 1e-6);
    EXPECT_NEAR(out.radiance.z, 0.4 + 0.1, 1e-6);
}

TEST(ReferenceShading, SkyIrradianceMatchesClosedFormForAGradedSky) {
    // L = 1 + 2 z above the horizon, 0 below, flat ground: E = pi + 4 pi / 3. 1e-6 relative
    // (float results).
    ReferenceScene s(21, 21, 30, [](double, double) { return 0.0; });
    const ReferenceShader ref(s.grid, s.mat, s.normals, s.view, {s.at(10, 10)}, no_curvature());
    const FunctionSky sky([](const glm::dvec3& d) { return d.z > 0 ? 1.0 + 2.0 * d.z : 0.0; }, {0, 0, 1}, 0.0);
    EXPECT_NEAR(ref.render(sky, sun_at(0, 90))[0].sky_irradiance.x, kPi + 4 * kPi / 3, 1e-6 * 7.33);
}

TEST(ReferenceShading, TiltedPlaneSeesExactlyItsHemisphere) {
    // An infinite plane tilted 25 degrees (facing east) under radiance 1 from the whole sphere:
    // the raymarched horizon is the plane itself in every azimuth, so E = pi exactly; the
    // quadrature's kink at the plane's own horizon is an end point. The horizon is stored as
    // float (1e-7 rad) where the integrand vanishes: 1e-6 relative.
    const double g = std::tan(radians(25));
    ReferenceScene s(61, 61, 30, [&](double x, double) { return 1000.0 - g * x; });
    const ReferenceShader ref(s.grid, s.mat, s.normals, s.view, {s.at(30, 30), s.at(20, 41)}, no_curvature());
    const FunctionSky sky([](const glm::dvec3&) { return 1.0; }, {0, 0, 1}, 0.0);
    for (const ReferenceSample& out : ref.render(sky, sun_at(0, 90))) {
        EXPECT_NEAR(out.sky_irradiance.x, kPi, 1e-6 * kPi);
        EXPECT_NEAR(out.radiance.y, 0.3, 1e-6);
    }
}

TEST(ReferenceShading, PhongLobeCutByTheTiltedPlaneMatchesBruteForce) {
    // A plane tilted 40 degrees seen from above: the mirror direction is 80 degrees from the
    // zenith, so the broad Phong lobe (alpha 2) is cut by the plane (n.w > 0). With radiance 1 from
    // everywhere the sky term is ks * integral over the plane's hemisphere of the lobe; brute
    // force here on a 4000 x 2000 (phi, z) midpoint grid, good to ~1e-5; 1e-4 relative.
    const double g = std::tan(radians(40));
    ReferenceScene s(61, 61, 30, [&](double, double y) { return 1000.0 - g * y; });  // faces south
    const std::size_t t = s.at(30, 30);
    s.mat.ks[t] = 1.0f, s.mat.alpha[t] = 2.0f;
    s.mat.albedo_r[t] = s.mat.albedo_g[t] = s.mat.albedo_b[t] = 0.0f;
    const ReferenceShader ref(s.grid, s.mat, s.normals, s.view, {t}, no_curvature());
    const FunctionSky sky([](const glm::dvec3&) { return 1.0; }, {0, 0, 1}, 0.0);
    const glm::dvec3 n(s.normals.x[t], s.normals.y[t], s.normals.z[t]);
    EXPECT_NEAR(n.z, std::cos(radians(40)), 1e-6);
    const glm::dvec3 r = 2.0 * n.z * n - glm::dvec3(0, 0, 1);
    double expected = 0;
    const int np = 4000, nz = 2000;
    for (int i = 0; i < np; ++i)
        for (int j = 0; j < nz; ++j) {
            const double phi = 2 * kPi * (i + 0.5) / np, z = -1 + 2.0 * (j + 0.5) / nz, q = std::sqrt(1 - z * z);
            const glm::dvec3 w(q * std::cos(phi), q * std::sin(phi), z);
            if (glm::dot(n, w) > 0 && glm::dot(r, w) > 0)
                expected += (2.0 + 1) / (2 * kPi) * std::pow(glm::dot(r, w), 2.0) * (2 * kPi / np) * (2.0 / nz);
        }
    EXPECT_LT(expected, 0.99) << "the lobe must be cut for this test to mean anything";
    EXPECT_NEAR(ref.render(sky, sun_at(0, 90))[0].radiance.x, expected, 1e-4 * expected);
}

TEST(ReferenceShading, PitBottomIrradianceMatchesClosedFormHorizon) {
    // Square pit z = k (|x| + |y|): from its bottom the horizon is atan(k (|cos| + |sin|))
    // exactly (horizons_test), so with radiance 1 above the horizon E = int cos^2(h(phi)) / 2
    // dphi, here by 200000 azimuths. The 720-wedge midpoint rule errs at the 4 kinks of h by
    // O(dphi^2): 1e-4 relative.
    const double k = 0.5;
    ReferenceScene s(81, 81, 30, [&](double x, double y) { return k * (std::abs(x) + std::abs(y)); });
    const ReferenceShader ref(s.grid, s.mat, s.normals, s.view, {s.at(40, 40)}, no_curvature());
    const FunctionSky sky([](const glm::dvec3&) { return 1.0; }, {0, 0, 1}, 0.0);
    double expected = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double phi = 2 * kPi * (i + 0.5) / n;
        const double hz = std::atan(k * (std::abs(std::cos(phi)) + std::abs(std::sin(phi))));
        expected += 0.5 * std::cos(hz) * std::cos(hz) * (2 * kPi / n);
    }
    EXPECT_NEAR(ref.render(sky, sun_at(0, 90))[0].sky_irradiance.x, expected, 1e-4 * expected);
}

TEST(ReferenceShading, WallShadowAndSunTerm) {
    // A north-south wall 100 m high on flat ground (10 m texels), the sun west of it at 30
    // degrees: texels east of it closer than H / tan(e) = 173 m get no sun, beyond get all of
    // it. Radiance = albedo (E_sky + f E_sun sin(e)) / pi with E_sky from the test's sky.
    const double H = 100.0;
    ReferenceScene s(80, 11, 10, [](double, double) { return 0.0; });
    for (int r = 0; r < 11; ++r) s.z[s.at(20, r)] = float(H);
    std::vector<std::size_t> texels;
    for (int c = 21; c < 60; ++c) texels.push_back(s.at(c, 5));
    const ReferenceShader ref(s.grid, s.mat, s.normals, s.view, texels, no_curvature());
    const SunState sun = sun_at(270, 30);
    const FunctionSky sky([](const glm::dvec3& d) { return d.z > 0 ? 0.5 : 0.0; }, sun_direction(sun), 100.0);
    const auto out = ref.render(sky, sun);
    for (std::size_t i = 0; i < texels.size(); ++i) {
        const double x = (double(i) + 1) * 10.0;                     // distance east of the wall
        if (std::abs(x - H / std::tan(radians(30))) < 10.0) continue;  // the shadow's edge texel
        const double f = x < H / std::tan(radians(30)) ? 0.0 : 1.0;
        EXPECT_EQ(out[i].sun_fraction, float(f)) << "x=" << x;
        const double expected = 0.2 * (out[i].sky_irradiance.x + f * 100.0 * std::sin(radians(30))) / kPi;
        EXPECT_NEAR(out[i].radiance.x, expected, 1e-5 * expected) << "x=" << x;
    }
    // The wall hides part of the sky from its foot: less than the open ground's 0.5 pi.
    EXPECT_LT(out[0].sky_irradiance.x, 0.5 * kPi * 0.9);
    EXPECT_NEAR(out.back().sky_irradiance.x, 0.5 * kPi, 0.5 * kPi * 0.01);
}

TEST(ReferenceShading, WaterIsAFresnelMirrorOverADarkBody) {
    // Flat water seen from straight above under radiance 1 and a sun at 40 degrees:
    // F(1) L(up) + (1 - F) 0.02 (E_sky + E_sun sin e) / pi, F(1) = ((n - 1)/(n + 1))^2. 1e-6.
    ReferenceScene s(21, 21, 30, [](double, double) { return 0.0; });
    const std::size_t t = s.at(10, 10);
    s.mat.water[t] = 1;
    const ReferenceShader ref(s.grid, s.mat, s.normals, s.view, {t}, no_curvature());
    const SunState sun = sun_at(120, 40);
    const FunctionSky sky([](const glm::dvec3&) { return 1.0; }, sun_direction(sun), 50.0);
    const double f = std::pow((kWaterIor - 1) / (kWaterIor + 1), 2);
    const double expected = f * 1.0 + (1 - f) * 0.02 * (kPi + 50.0 * std::sin(radians(40))) / kPi;
    EXPECT_NEAR(ref.render(sky, sun)[0].radiance.x, expected, 1e-6);
    EXPECT_NEAR(f, material::fresnel_dielectric(1.0, 1.0, kWaterIor), 1e-12);
}

TEST(ReferenceShading, SunVisibilityOfEveryTexelMatchesRaymarchedHorizons) {
    // reference_sun_visibility stops its marches once the answer is known; its fraction must
    // equal the one from the full raymarch horizon in the same azimuth (D = 8 holds azimuth
    // 45 exactly). The horizon set stores angles as float (3e-8 rad at 0.5 rad) and the
    // fraction changes by up to 2 / (pi r) = 137 per radian on the disc: 1e-5.
    ReferenceScene s(70, 60, 30, [](double x, double y) {
        return 300.0 * std::sin(x / 900.0) * std::cos(y / 1300.0) + 120.0 * std::sin((x + 2 * y) / 400.0);
    });
    visibility::HorizonOptions o;
    o.method = visibility::HorizonMethod::raymarch;
    o.directions = 8;
    o.curvature = true;
    o.threads = 2;
    const visibility::HorizonSet set = visibility::compute_horizons(s.grid, o);
    const double az = visibility::user_azimuth_deg(1, 8);
    for (double e : {3.0, 10.0, 30.0}) {
        const std::vector<float> vis = reference_sun_visibility(s.grid, az, e, 0.004654, true, 2);
        int partial = 0;
        for (std::size_t i = 0; i < vis.size(); ++i) {
            const double f = visibility::sun_disc_visible_fraction(set.plane(1)[i], radians(e), 0.004654);
            ASSERT_NEAR(vis[i], f, 1e-5) << "e=" << e << " i=" << i;
            partial += f < 1;
        }
        if (e == 10.0) {
            EXPECT_GT(partial, 0) << "the test needs shadows";
        }
    }
}

TEST(ReferenceShading, RejectsMismatchedInputs) {
    ReferenceScene s(10, 10, 30, [](double, double) { return 0.0; });
    EXPECT_THROW(ReferenceShader(s.grid, s.mat, s.normals, s.view, {1000}), InputError);
    MaterialRaster small;
    EXPECT_THROW(ReferenceShader(s.grid, small, s.normals, s.view, {0}), InputError);
}
