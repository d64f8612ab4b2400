// GLSL and C++ evaluate the same core/blockers/sphere_occlusion_shared.h: the flythrough's
// shaders shadow the terrain and the aircraft with the formula the CPU's blockers use (the
// sun's disc covered by a sphere, the sky a sphere hides). A compute shader evaluates it in
// float on the Vulkan device (lavapipe without a GPU), the C++ side the same text in double on
// the same float inputs; the validation layer is on and must stay silent.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <gtest/gtest.h>

#include "core/blockers/sphere_occlusion_shared.hpp"
#include "core/blockers/sun_disc_occlusion.hpp"
#include "gpu/batch.hpp"
#include "gpu/spirv.hpp"
#include "tests/gpu/validated_context.hpp"

namespace ts::gpu::embedded {
extern const SpirvBlob sphere_occlusion_agreement_comp;  // tests/gpu/shaders/sphere_occlusion_agreement.comp
}

namespace ts::gpu::sphere_occlusion_agreement {
namespace {

struct Push {
    std::uint32_t count;
};

using SphereOcclusionAgreementTest = test_support::ValidatedTest;

glm::dvec3 to_double(const glm::vec4& v) { return {double(v.x), double(v.y), double(v.z)}; }

// Spheres 15 m to 3 km from a receiver near the origin, 0.3 to 20 m across, placed at a
// separation from the sun's centre that sweeps the penumbra (cap -1.5 alpha .. cap +1.5 alpha),
// plus inside the sphere and far from the sun; normals from straight up to 80 degrees off, so
// the sky cover meets caps above, across and below the tangent plane.
std::vector<glm::vec4> make_cases() {
    std::mt19937 rng(16);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<glm::vec4> cases;
    const double alpha = blockers::kSunAngularRadiusRad;
    for (int i = 0; i < 6000; ++i) {
        const double el = 0.1 + 1.4 * u(rng), az = 6.283 * u(rng);
        const glm::dvec3 sun(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
        const double d = 15.0 * std::pow(200.0, u(rng)), r = std::min(0.3 + 19.7 * u(rng), 0.9 * d);
        const double cap = std::asin(r / d);
        double sep = cap + alpha * (3.0 * u(rng) - 1.5);
        if (i % 10 == 0) sep = 0.2 + u(rng);  // far from the sun: sky only
        sep = std::max(sep, 0.0);
        // A unit vector `sep` from the sun about a random axis perpendicular to it.
        const glm::dvec3 a = glm::normalize(glm::cross(sun, glm::dvec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5)));
        const glm::dvec3 dir = std::cos(sep) * sun + std::sin(sep) * a;
        const glm::dvec3 receiver(200.0 * (u(rng) - 0.5), 200.0 * (u(rng) - 0.5), 300.0 * u(rng));
        glm::dvec3 centre = receiver + d * dir;
        if (i % 50 == 1) centre = receiver + 0.5 * r * dir;  // inside
        const double tilt = 1.4 * u(rng), tilt_az = 6.283 * u(rng);
        const glm::dvec3 n(std::sin(tilt) * std::cos(tilt_az), std::sin(tilt) * std::sin(tilt_az), std::cos(tilt));
        cases.push_back(glm::vec4(glm::vec3(centre), float(r)));
        cases.push_back(glm::vec4(glm::vec3(receiver), float(alpha)));
        cases.push_back(glm::vec4(glm::vec3(sun), 0.0f));
        cases.push_back(glm::vec4(glm::vec3(n), 0.0f));
    }
    return cases;
}

TEST_F(SphereOcclusionAgreementTest, SunAndSkyCoversAgreeWithTheCpu) {
    const Context& context = *context_;
    const Kernel kernel(context, "sphere_occlusion_agreement.comp", embedded::sphere_occlusion_agreement_comp.words,
                        {.storage_buffers = 2, .push_constant_bytes = sizeof(Push)});
    const std::vector<glm::vec4> cases = make_cases();
    const auto count = std::uint32_t(cases.size() / 4);
    const Buffer in = context.create_buffer(cases.size() * sizeof(glm::vec4));
    const Buffer out = context.create_buffer(std::size_t(count) * 2 * sizeof(float));
    std::vector<float> gpu(std::size_t(count) * 2);
    Batch batch(context);
    batch.upload(in, std::span<const glm::vec4>(cases));
    batch.dispatch(kernel, {in, out}, Push{count}, groups_for(count, 64));
    batch.download(out, std::span<float>(gpu));
    batch.submit_and_wait();

    // Float against double on the same inputs. The sun cover turns on the separation minus the
    // cap's half-angle against a disc of 4.7e-3 rad (a fraction of 1 per 9.3e-3 rad), so it
    // follows the device's asin and atan: lavapipe's are off by up to ~4e-4 rad near 1 rad (the
    // Vulkan spec allows 4096 ulp), a fraction of 0.05, for caps wider than 0.3 rad (receivers
    // within 3.4 radii: the aircraft's own surface, not the terrain below it). Smaller caps are
    // held to 1e-3. The sky cover: relative float rounding and the device's acos and atan
    // where the cap straddles the tangent plane.
    constexpr double kSunTolerance = 1e-3, kWideCapSunTolerance = 0.06, kWideCap = 0.3;
    constexpr double kSkyRelative = 3e-3, kSkyAbsolute = 1e-5;
    double worst_sun = 0, worst_wide_sun = 0, worst_sky = 0;
    int penumbra = 0, umbra = 0, straddling = 0;
    for (std::uint32_t i = 0; i < count; ++i) {
        const glm::dvec3 c = to_double(cases[4 * i]), p = to_double(cases[4 * i + 1]);
        const glm::dvec3 s = to_double(cases[4 * i + 2]), n = to_double(cases[4 * i + 3]);
        const double r = cases[4 * i].w, alpha = cases[4 * i + 1].w;
        const double sun = blockers::shared::ts_sphere_sun_cover(c, r, p, s, alpha);
        const double sky = blockers::shared::ts_sphere_sky_cover(c, r, p, n);
        // The CPU's blockers are this text.
        ASSERT_EQ(blockers::sphere_sun_cover({c, r}, p, s, alpha), sun);
        ASSERT_EQ(blockers::sphere_sky_cover({c, r}, p, n), sky);
        const double g_sun = gpu[2 * i], g_sky = gpu[2 * i + 1];
        ASSERT_TRUE(std::isfinite(g_sun) && std::isfinite(g_sky)) << "case " << i;
        const bool wide = std::asin(std::min(1.0, r / glm::length(c - p))) > kWideCap;
        double& worst = wide ? worst_wide_sun : worst_sun;
        worst = std::max(worst, std::abs(g_sun - sun));
        worst_sky = std::max(worst_sky, std::abs(g_sky - sky) / (kSkyAbsolute / kSkyRelative + sky));
        EXPECT_NEAR(g_sun, sun, wide ? kWideCapSunTolerance : kSunTolerance) << "case " << i;
        EXPECT_NEAR(g_sky, sky, kSkyAbsolute + kSkyRelative * sky) << "case " << i;
        penumbra += sun > 0.01 && sun < 0.99;
        umbra += sun == 1.0;
        const double cos_b = glm::dot(glm::normalize(c - p), n), s2 = r * r / glm::dot(c - p, c - p);
        straddling += cos_b * cos_b <= s2;
    }
    std::printf("%u cases (%d penumbra, %d umbra, %d caps across the tangent plane): worst |GPU - C++| sun %.2e "
                "(caps within %.1f rad), %.2e (wider), sky %.2e relative\n",
                count, penumbra, umbra, straddling, worst_sun, kWideCap, worst_wide_sun, worst_sky);
    // The cases reach every branch.
    EXPECT_GT(penumbra, 1000);
    EXPECT_GT(umbra, 100);
    EXPECT_GT(straddling, 20);
}

}  // namespace
}  // namespace ts::gpu::sphere_occlusion_agreement
