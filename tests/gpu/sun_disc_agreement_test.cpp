// GLSL and C++ evaluate the same core/visibility/sun_disc_shared.h: the flythrough's fragments
// shade the sun's disc above their interpolated horizon with the fraction the CPU's sun
// visibility uses. A compute shader evaluates it in float on the Vulkan device (lavapipe without
// a GPU), the C++ side the same text in double on the same float inputs; the validation layer
// is on and must stay silent.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "core/visibility/sun_disc_shared.hpp"
#include "core/visibility/sun_visibility.hpp"
#include "gpu/batch.hpp"
#include "gpu/spirv.hpp"
#include "tests/gpu/validated_context.hpp"

namespace ts::gpu::embedded {
extern const SpirvBlob sun_disc_agreement_comp;  // tests/gpu/shaders/sun_disc_agreement.comp
}

namespace ts::gpu::sun_disc_agreement {
namespace {

struct Push {
    std::uint32_t count;
};

using SunDiscAgreementTest = test_support::ValidatedTest;

TEST_F(SunDiscAgreementTest, TheDiscsVisibleFractionAgreesWithTheCpu) {
    const Context& context = *context_;
    const Kernel kernel(context, "sun_disc_agreement.comp", embedded::sun_disc_agreement_comp.words,
                        {.storage_buffers = 2, .push_constant_bytes = sizeof(Push)});
    // Across the disc finely, its rims, and beyond them on both sides.
    std::vector<float> cases;
    for (int i = 0; i <= 4000; ++i) cases.push_back(float(-1.5 + 3.0 * i / 4000.0));
    for (float x : {-1.0f, 1.0f, 0.0f, -1e-4f, 1e-4f, 0.9999f, -0.9999f, 50.0f, -50.0f}) cases.push_back(x);
    const auto count = std::uint32_t(cases.size());
    const Buffer in = context.create_buffer(cases.size() * sizeof(float));
    const Buffer out = context.create_buffer(cases.size() * sizeof(float));
    std::vector<float> gpu(cases.size());
    Batch batch(context);
    batch.upload(in, std::span<const float>(cases));
    batch.dispatch(kernel, {in, out}, Push{count}, groups_for(count, 64));
    batch.download(out, std::span<float>(gpu));
    batch.submit_and_wait();

    // Float against double: acos near x = +-1 is where float loses most (the fraction changes
    // by ~x^1.5 there), 1e-4 of the disc is far below a code on any picture.
    constexpr double kTolerance = 1e-4;
    const double radius = 0.004654, e = 0.3;
    double worst = 0;
    for (std::uint32_t i = 0; i < count; ++i) {
        const double cpu = visibility::shared::ts_sun_disc_fraction(double(cases[i]));
        // The CPU's sun visibility is this text.
        ASSERT_NEAR(visibility::sun_disc_visible_fraction(e - double(cases[i]) * radius, e, radius), cpu, 1e-12);
        ASSERT_TRUE(std::isfinite(gpu[i])) << "x " << cases[i];
        worst = std::max(worst, std::abs(double(gpu[i]) - cpu));
        EXPECT_NEAR(gpu[i], cpu, kTolerance) << "x " << cases[i];
    }
    std::printf("%u cases: worst |GPU - C++| %.2e\n", count, worst);
    EXPECT_EQ(gpu[count - 2], 1.0f);
    EXPECT_EQ(gpu[count - 1], 0.0f);
}

// The inverse the renderer gives a texel darkened by other shadows: the horizon that leaves its
// fraction.
TEST(SunDiscInverse, GivesTheHorizonThatLeavesTheFraction) {
    const double radius = 0.004654;
    for (double v : {0.0, 1e-3, 0.1, 0.5, 0.77, 0.999, 1.0}) {
        const double h = visibility::horizon_above_sun_for_fraction(v, radius);
        EXPECT_LE(std::abs(h), radius * (1 + 1e-9));
        EXPECT_NEAR(visibility::shared::ts_sun_disc_fraction(-h / radius), v, 1e-9) << v;
    }
    EXPECT_NEAR(visibility::horizon_above_sun_for_fraction(0.5, radius), 0.0, 1e-12);
}

}  // namespace
}  // namespace ts::gpu::sun_disc_agreement
