#include "core/material/brdf.hpp"
#include "core/util/angles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "core/material/albedo.hpp"
#include "core/sh/log_scenes.hpp"

namespace ts::material {
namespace {

const glm::dvec3 kN(0, 0, 1);

using Brdf = std::function<double(const glm::dvec3&, const glm::dvec3&)>;

struct Named {
    std::string name;
    Brdf f;
    bool reciprocal;
};

CookTorrance ct(Distribution d, Geometry g, FresnelModel f, double roughness) {
    CookTorrance p;
    p.distribution = d;
    p.geometry = g;
    p.fresnel = f;
    p.roughness = roughness;
    p.eta = f == FresnelModel::conductor ? 0.370 : 1.5;  // gold or glass
    p.k = f == FresnelModel::conductor ? 2.820 : 0.0;
    return p;
}

std::vector<Named> models() {
    std::vector<Named> m;
    m.push_back({"lambert", [](auto&, auto&) { return lambert(0.8); }, true});
    m.push_back({"phong", [](auto& i, auto& o) { return phong(i, o, kN, 0.5, 20); }, false});
    m.push_back({"phong_normalized", [](auto& i, auto& o) { return phong_normalized(i, o, kN, 1.0, 20); }, true});
    m.push_back({"blinn_phong", [](auto& i, auto& o) { return blinn_phong(i, o, kN, 0.5, 20); }, false});
    m.push_back(
        {"blinn_phong_normalized", [](auto& i, auto& o) { return blinn_phong_normalized(i, o, kN, 1.0, 20); }, true});
    m.push_back({"ward", [](auto& i, auto& o) { return ward(i, o, kN, 0.5, 0.3, 0.15); }, true});
    for (Distribution d : {Distribution::beckmann, Distribution::ggx})
        for (Geometry g : {Geometry::smith, Geometry::vgroove})
            for (FresnelModel f :
                 {FresnelModel::dielectric, FresnelModel::conductor, FresnelModel::schlick, FresnelModel::none}) {
                const CookTorrance p = ct(d, g, f, 0.3);
                m.push_back({"cook_torrance d" + std::to_string(int(d)) + " g" + std::to_string(int(g)) + " f" +
                                 std::to_string(int(f)),
                             [p](auto& i, auto& o) { return cook_torrance(i, o, kN, p); }, true});
            }
    return m;
}

glm::dvec3 random_upper(sh::SplitMix64& rng) {
    const double z = rng.uniform(0.001, 1.0), phi = rng.uniform(0.0, 2 * kPi), r = std::sqrt(1 - z * z);
    return {r * std::cos(phi), r * std::sin(phi), z};
}

glm::dvec3 incident(double theta_deg) {
    const double t = radians(theta_deg);
    return {std::sin(t), 0.0, std::cos(t)};
}

TEST(Brdf, NonNegativeAndZeroBelowTheSurface) {
    sh::SplitMix64 rng(101);
    for (const Named& m : models())
        for (int t = 0; t < 2000; ++t) {
            const glm::dvec3 i = random_upper(rng), o = random_upper(rng);
            const double v = m.f(i, o);
            ASSERT_TRUE(std::isfinite(v)) << m.name;
            ASSERT_GE(v, 0.0) << m.name;
            if (m.name != "lambert") {
                ASSERT_EQ(m.f(i, -o), 0.0) << m.name;
            }
        }
}

TEST(Brdf, HelmholtzReciprocityWhereClaimed) {
    sh::SplitMix64 rng(103);
    for (const Named& m : models()) {
        double worst = 0.0;
        for (int t = 0; t < 2000; ++t) {
            const glm::dvec3 i = random_upper(rng), o = random_upper(rng);
            const double a = m.f(i, o), b = m.f(o, i);
            worst = std::max(worst, std::abs(a - b) / std::max(1e-12, std::max(a, b)));
        }
        if (m.reciprocal) {
            EXPECT_LT(worst, 1e-12) << m.name;  // symmetric formulas: round-off only
        } else {
            EXPECT_GT(worst, 1e-2) << m.name << " is documented as not reciprocal";
        }
    }
}

TEST(Brdf, EnergyConservationForEveryIncidentAngle) {
    // 256 x 512 points: lobes here are at most ~0.15 rad wide; quadrature error < 1e-3.
    const HemisphereRule rule = cosine_hemisphere_rule(256, 512);
    for (const Named& m : models()) {
        if (m.name == "phong" || m.name == "blinn_phong") continue;  // not energy conserving (lecture)
        for (double deg = 0.0; deg <= 89.0; deg += 8.0) {
            const double a = directional_albedo(m.f, incident(deg), rule);
            // The (n+8)/(8 pi) Blinn-Phong normalisation is an approximation that overshoots
            // near normal incidence (measured 1.061 at n = 20): its documented bound is 1.07 ks.
            const double bound = m.name == "blinn_phong_normalized" ? 1.07 : 1.0;
            EXPECT_LE(a, bound + 2e-3) << m.name << " at " << deg << " deg";
        }
    }
}

TEST(Brdf, KnownClosedFormAlbedos) {
    const HemisphereRule rule = cosine_hemisphere_rule(256, 512);
    // Lambert: albedo = rho at every angle.
    for (double deg : {0.0, 45.0, 80.0})
        EXPECT_NEAR(directional_albedo([](auto&, auto&) { return lambert(0.7); }, incident(deg), rule), 0.7, 1e-9);
    // Normalised Phong at normal incidence: the lobe lies in the hemisphere, albedo = ks.
    for (double ke : {1.0, 5.0, 20.0})
        EXPECT_NEAR(directional_albedo([&](auto& i, auto& o) { return phong_normalized(i, o, kN, 0.6, ke); },
                                       incident(0.0), rule),
                    0.6, 1e-4)
            << ke;
    // The slides' normalised Phong lobe (alpha+1)/(2pi) cos^alpha integrates to 1 over the
    // hemisphere (no cosine weight): check with the rule's weights divided by cos.
    for (double alpha : {1.0, 10.0, 100.0}) {
        double s = 0.0;
        for (std::size_t p = 0; p < rule.directions.size(); ++p)
            s += rule.weights[p] / rule.directions[p].z * (alpha + 1) / (2 * kPi) *
                 std::pow(rule.directions[p].z, alpha);
        EXPECT_NEAR(s, 1.0, 1e-6) << alpha;
    }
    // Cook-Torrance, F = 1, smooth GGX at normal incidence: almost no masking, albedo -> 1.
    const CookTorrance p = ct(Distribution::ggx, Geometry::smith, FresnelModel::none, 0.1);
    const double a =
        directional_albedo([&](auto& i, auto& o) { return cook_torrance(i, o, kN, p); }, incident(0.0), rule);
    EXPECT_NEAR(a, 1.0, 0.02);  // Smith masking at alpha 0.1 removes < 1%
}

}  // namespace
}  // namespace ts::material
