#include "core/blockers/sphere_log_sh_kernel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

namespace ts::blockers {
namespace {

// The kernel (float, lanes) against accumulate_blockers (double, one sphere at a time): the
// same formulas, so they differ by float rounding only: a few 1e-6 of the largest coefficient,
// here bounded at 2e-5 of it (plus 1e-6 absolute).
void expect_agrees(const std::vector<Sphere>& spheres, const glm::dvec3& receiver, const glm::dvec3& normal,
                   const RatioAttenuation& options, const char* what) {
    const double log_eps = -1.0;
    const sh::ShVec want = accumulate_blockers(spheres, receiver, normal, log_eps, options);
    float got[16] = {};
    accumulate_sphere_lanes(SphereLanes(spheres), glm::vec3(receiver), glm::vec3(normal), float(log_eps), options, got);
    double scale = 0.0;
    for (double v : want) scale = std::max(scale, std::abs(v));
    for (int i = 0; i < 16; ++i) {
        ASSERT_TRUE(std::isfinite(got[i])) << what << " coefficient " << i;
        EXPECT_NEAR(got[i], want[std::size_t(i)], 2e-5 * scale + 1e-6) << what << " coefficient " << i;
    }
}

std::vector<Sphere> random_spheres(std::mt19937& rng, int n, double spread, double r0, double r1) {
    std::uniform_real_distribution<double> u(-spread, spread), ur(r0, r1);
    std::vector<Sphere> out;
    for (int i = 0; i < n; ++i) out.push_back({{u(rng), u(rng), u(rng) + 0.5 * spread}, ur(rng)});
    return out;
}

TEST(SphereLogShKernel, AgreesWithTheDoubleAccumulationForEveryCountAndOption) {
    std::mt19937 rng(7);
    const glm::dvec3 receiver(3.0, -2.0, 1.0);
    const glm::dvec3 normal = glm::normalize(glm::dvec3(0.3, -0.2, 1.0));
    // Counts around the lane width (padding), with and without each attenuation control.
    for (int n : {1, 2, 15, 16, 17, 31, 64, 100, 400})
        for (bool cull : {false, true})
            for (bool ratio : {false, true}) {
                std::vector<Sphere> s = random_spheres(rng, n, 40.0, 0.5, 6.0);
                for (Sphere& x : s) x.center += receiver;
                RatioAttenuation o;
                o.cull_lower_hemisphere = cull, o.solid_angle_ratio = ratio;
                expect_agrees(s, receiver, normal, o, ("n=" + std::to_string(n)).c_str());
            }
}

TEST(SphereLogShKernel, AReceiverInsideOrOnASphereIsWhollyBlocked) {
    // One sphere holding the receiver: the whole sphere of directions at log_eps, as in double.
    const glm::dvec3 q(10.0, 20.0, 30.0);
    expect_agrees({{q + glm::dvec3(0.5, 0.0, 0.0), 2.0}}, q, {0, 0, 1}, {}, "inside");
    expect_agrees({{q, 1.0}}, q, {0, 0, 1}, {}, "at the centre");
    expect_agrees({{q + glm::dvec3(0.0, 0.0, 1.0), 1.0}}, q, {0, 0, 1}, {}, "on the surface");
    float got[16] = {};
    accumulate_sphere_lanes(SphereLanes(std::vector<Sphere>{{q, 1.0}}), glm::vec3(q), {0, 0, 1}, -1.0f,
                            RatioAttenuation{true, false}, got);
    EXPECT_NEAR(got[0], -3.5449077, 1e-5);  // -sqrt(4 pi): log_eps over the whole sphere
    for (int i = 1; i < 16; ++i) EXPECT_NEAR(got[i], 0.0, 1e-6);
}

TEST(SphereLogShKernel, PaddingAndZeroRadiusSpheresAddNothing) {
    // Padding lanes are skipped (a receiver at the frame origin, where the padding lies, too);
    // a sphere of radius 0 away from the receiver subtends nothing.
    const std::vector<Sphere> one{{{0.0, 0.0, 10.0}, 2.0}};
    float a[16] = {}, b[16] = {};
    accumulate_sphere_lanes(SphereLanes(one), {0, 0, 0}, {0, 0, 1}, -1.0f, {}, a);
    std::vector<Sphere> with_point = one;
    with_point.push_back({{5.0, 5.0, 5.0}, 0.0});
    accumulate_sphere_lanes(SphereLanes(with_point), {0, 0, 0}, {0, 0, 1}, -1.0f, {}, b);
    for (int i = 0; i < 16; ++i) EXPECT_EQ(a[i], b[i]) << i;
    expect_agrees(one, {0, 0, 0}, {0, 0, 1}, {}, "one sphere over the origin");
}

TEST(SphereLogShKernel, FiveHundredOverlappingSpheresStayFiniteAndBounded) {
    // The stability case of the method: 500 spheres piled over the receiver. With the ratio the
    // kept caps claim at most the hemisphere: the DC term is at least log_eps * 2 pi / sqrt(4 pi)
    // (the hemisphere at log_eps), whatever the pile.
    std::mt19937 rng(11);
    std::vector<Sphere> s = random_spheres(rng, 500, 3.0, 1.0, 2.0);
    for (Sphere& x : s) x.center.z += 3.0;
    float got[16] = {};
    accumulate_sphere_lanes(SphereLanes(s), {0, 0, 0}, {0, 0, 1}, -1.0f, {}, got);
    for (float v : got) ASSERT_TRUE(std::isfinite(v));
    EXPECT_GE(got[0], -6.2831853 / 3.5449077 - 1e-4);
    expect_agrees(s, {0, 0, 0}, {0, 0, 1}, {}, "500 overlapping");
}

TEST(SphereLogShKernel, AddsToWhatTheOutputHolds) {
    const std::vector<Sphere> one{{{1.0, 2.0, 8.0}, 1.5}};
    float a[16] = {}, b[16];
    for (float& v : b) v = 0.25f;
    accumulate_sphere_lanes(SphereLanes(one), {0, 0, 0}, {0, 0, 1}, -1.0f, {}, a);
    accumulate_sphere_lanes(SphereLanes(one), {0, 0, 0}, {0, 0, 1}, -1.0f, {}, b);
    for (int i = 0; i < 16; ++i) EXPECT_FLOAT_EQ(b[i], a[i] + 0.25f) << i;
}

}  // namespace
}  // namespace ts::blockers
