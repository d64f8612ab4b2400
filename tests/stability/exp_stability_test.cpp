// Stability of SH exponentiation under many overlapping sphere blockers (up to 500 around one
// receiver, a dense mesh's decomposition): the summed log vector grows with the count, and
// with it the exponentiation error. The reference is the true visibility projected to order 4
// (exp of the un-truncated log, on a 1-degree grid): against the exact exponential of the
// band-limited log (core/sh/exact_exp.hpp) the error means nothing at 500 caps, because that
// log rings far above zero and its exponential is huge. Expected: no NaN or infinity for any
// method, and for the methods the pipeline uses (hybrid for visibility, scaling_squaring for
// the renderer's transfer) an error against the true visibility that stays bounded as the
// count grows: tight with ratio attenuation (the renderer's default), loose without it (the
// raw sum, where scaling_squaring overshoots: docs/accuracy.md, "Failure modes").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>

#include "core/blockers/sphere_blocker.hpp"
#include "core/sh/exp_method.hpp"
#include "core/sh/log_scenes.hpp"
#include "core/sh/sh_basis.hpp"
#include "core/sh/sh_exp.hpp"
#include "core/sh/sphere_quadrature.hpp"

namespace ts::stability {
namespace {

// `count` spheres of radius 2..10 m centred 5..40 m above a 60 x 60 m square around the
// receiver at the origin: they overlap each other and cover much of the sky.
std::vector<blockers::Sphere> sphere_cloud(int count, std::uint64_t seed) {
    sh::SplitMix64 rng(seed);
    std::vector<blockers::Sphere> s;
    for (int i = 0; i < count; ++i)
        s.push_back({{rng.uniform(-30, 30), rng.uniform(-30, 30), rng.uniform(5, 40)}, rng.uniform(2, 10)});
    return s;
}

struct ExpResult {
    sh::ShVec v{};
    bool finite = true;
};

ExpResult exponentiate(sh::ExpMethod method, const sh::ShVec& f) {
    float in[sh::kCount], out[sh::kCount];
    for (int i = 0; i < sh::kCount; ++i) in[i] = float(f[i]);
    sh::sh_exp(method, in, out);
    ExpResult r;
    for (int i = 0; i < sh::kCount; ++i) {
        r.v[i] = out[i];
        r.finite = r.finite && std::isfinite(out[i]);
    }
    return r;
}

// RMS over the sphere of the difference (orthonormal basis).
double rms(const sh::ShVec& a, const sh::ShVec& b) {
    return sh::norm(sh::operator-(a, b)) / sh::kSqrt4Pi;
}

TEST(StabilityExp, FiveHundredOverlappingSpheresStayFiniteWithBoundedErrorAgainstTheTrueVisibility) {
    const sh::SphereQuadrature truth_grid(90, 180);  // 2-degree grid: cap edges to a degree
    const glm::dvec3 receiver{0, 0, 0}, normal{0, 0, 1};
    const double log_eps = -2.302585092994046;  // the visibility floor the renderer uses
    for (bool attenuate : {true, false}) {
        blockers::RatioAttenuation ra;
        ra.solid_angle_ratio = attenuate;
        for (int count : {1, 16, 64, 500}) {
            const auto spheres = sphere_cloud(count, 17 + std::uint64_t(count));
            const sh::ShVec f = blockers::accumulate_blockers(spheres, receiver, normal, log_eps, ra);
            for (double v : f) {
                ASSERT_TRUE(std::isfinite(v)) << count << " spheres: non-finite log vector";
            }
            // True visibility: exp of the weighted sum of log_eps over the caps covering d.
            const std::vector<double> w = blockers::ratio_attenuation_weights(spheres, receiver, normal, ra);
            const sh::ShVec truth = truth_grid.project([&](const glm::dvec3& d) {
                double lv = 0;
                for (std::size_t b = 0; b < spheres.size(); ++b) {
                    const glm::dvec3 to = spheres[b].center - receiver;
                    const double dist = glm::length(to);
                    if (glm::dot(d, to / dist) >= std::cos(blockers::sphere_theta_b(spheres[b].radius, dist)))
                        lv += w[b] * log_eps;
                }
                return std::exp(lv);
            });
            for (sh::ExpMethod m : sh::kAllExpMethods) {
                const ExpResult e = exponentiate(m, f);
                const std::string what = std::string(sh::to_string(m)) + ", " + std::to_string(count) + " spheres" +
                                         (attenuate ? ", ratio attenuation" : ", raw sum");
                ASSERT_TRUE(e.finite) << what;
                const double err = rms(e.v, truth);
                // The pipeline's methods: the error does not grow with the count. Measured
                // (both methods, with or without attenuation): 0.05 for 1 sphere, 0.21 for 16,
                // 0.14-0.23 for 64, 0.05-0.06 for 500 (the sky almost all blocked: a simple
                // visibility again). Most of it is the log-domain order-4 approximation of sharp
                // cap edges, not the exponentiation. Bound 0.3 at every count.
                if (m == sh::ExpMethod::scaling_squaring || m == sh::ExpMethod::hybrid) {
                    EXPECT_LT(err, 0.3) << what;
                }
            }
        }
    }
}

TEST(StabilityExp, RawSumsOfFiveHundredRandomCapsStayFiniteAndBounded) {
    // Random scenes without ratio attenuation (core/sh/log_scenes: caps of 2..20 degrees, floor
    // log 0.001, the bench sh study's scenes): the log vector's magnitude grows to ~100 at 500
    // caps. No method may return NaN. The error against the true visibility grows: measured
    // mean RMS, 16 -> 500 caps: hybrid 0.39 -> 0.69, scaling_squaring 0.41 -> 5.5 (its result
    // overshoots far above 1 where the band-limited log rings), Taylor 1e8. This is why the
    // renderer applies ratio attenuation to blockers (test above: <= 0.052 at 500 spheres)
    // and why the visibility's default is hybrid. Bounds at about twice the measured figures.
    const sh::SphereQuadrature truth_grid(90, 180);
    for (auto [m, bound16, bound500] : {std::tuple{sh::ExpMethod::scaling_squaring, 0.8, 11.0},
                                        std::tuple{sh::ExpMethod::hybrid, 0.8, 1.4}}) {
        double mean_error[2] = {0, 0};
        const int counts[2] = {16, 500};
        for (int k = 0; k < 2; ++k) {
            sh::SplitMix64 rng(99);
            sh::SceneOptions so;
            so.blockers = counts[k];
            for (int s = 0; s < 4; ++s) {
                const sh::LogScene scene = sh::random_scene(so, rng);
                const ExpResult e = exponentiate(m, scene.log_sh());
                ASSERT_TRUE(e.finite);
                const sh::ShVec truth =
                    truth_grid.project([&](const glm::dvec3& d) { return std::exp(scene.true_log(d)); });
                mean_error[k] += rms(e.v, truth) / 4;
            }
        }
        std::printf("%s: mean rms vs true visibility, 16 caps %.4f, 500 caps %.4f\n", sh::to_string(m).data(),
                    mean_error[0], mean_error[1]);
        EXPECT_LT(mean_error[0], bound16) << sh::to_string(m);
        EXPECT_LT(mean_error[1], bound500) << sh::to_string(m);
    }
}

}  // namespace
}  // namespace ts::stability
