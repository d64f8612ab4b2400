// GLSL and C++ evaluate the same core/raster/display_shared.h: the flythrough's shaders and the
// 8-bit encoders of every picture (tone_map.hpp, srgb.hpp) apply one display transform. A
// compute shader evaluates it on the Vulkan device (lavapipe without a GPU), the C++ side
// the same text in float; the validation layer is on and must stay silent.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <gtest/gtest.h>

#include "core/raster/display_shared.hpp"
#include "core/raster/srgb.hpp"
#include "core/render/tone_map.hpp"
#include "gpu/batch.hpp"
#include "gpu/spirv.hpp"
#include "tests/gpu/validated_context.hpp"

namespace ts::gpu::embedded {
extern const SpirvBlob display_agreement_comp;  // tests/gpu/shaders/display_agreement.comp
}

namespace ts::gpu::display_agreement {
namespace {

struct Push {
    std::uint32_t count;
};

using DisplayAgreementTest = test_support::ValidatedTest;

// Exposed pixels from far below black to far above white, dense around the sRGB knee
// (0.0031308) and the filmic curve's shoulder, plus the ends and out-of-range inputs: each
// value as a grey, as the largest of a warm and of a cool colour, and with a negative channel.
std::vector<glm::vec3> make_inputs() {
    std::vector<float> x = {-1.0f, -1e-6f, 0.0f, 0.0031308f, 1.0f, 7.24f, 8.0f, 1e3f, 1e6f};
    for (int i = 0; i <= 4000; ++i) x.push_back(std::pow(10.0f, -6.0f + 9.0f * float(i) / 4000));
    for (int i = 0; i <= 1000; ++i) x.push_back(0.002f + 0.003f * float(i) / 1000);
    std::vector<glm::vec3> px;
    for (float v : x) {
        px.emplace_back(v);
        px.emplace_back(v, 0.45f * v, 0.08f * v);
        px.emplace_back(0.2f * v, 0.55f * v, v);
        px.emplace_back(v, -0.1f * v, 0.3f * v);
    }
    return px;
}

TEST_F(DisplayAgreementTest, TheFilmicGainAndSrgbAgreeWithTheEncoders) {
    const Context& context = *context_;
    const Kernel kernel(context, "display_agreement.comp", embedded::display_agreement_comp.words,
                        {.storage_buffers = 2, .push_constant_bytes = sizeof(Push)});
    const std::vector<glm::vec3> inputs = make_inputs();
    const auto count = std::uint32_t(inputs.size());
    std::vector<float> flat;
    for (const glm::vec3& c : inputs) flat.insert(flat.end(), {c.x, c.y, c.z});
    const Buffer in = context.create_buffer(flat.size() * sizeof(float));
    const Buffer out = context.create_buffer(inputs.size() * 4 * sizeof(float));
    std::vector<float> gpu(inputs.size() * 4);
    Batch batch(context);
    batch.upload(in, std::span<const float>(flat));
    batch.dispatch(kernel, {in, out}, Push{count}, groups_for(count, 64));
    batch.download(out, std::span<float>(gpu));
    batch.submit_and_wait();

    // Both are float: the gain to 1e-6 relative (a division each side), the encoded values
    // (in [0, 1]) to 1e-6 absolute, as the GLSL pow is bounded loosely by the Vulkan spec (a few
    // ulp); the 8-bit code may then differ by one only for a value that lands within that of a
    // rounding boundary.
    constexpr double kTolerance = 1e-6;
    double worst_gain = 0, worst_value = 0;
    int codes_off_by_one = 0;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const glm::vec3 x = inputs[i];
        const glm::vec3 c = glm::max(x, glm::vec3(0.0f));
        const float gain = raster::shared::ts_display_gain(c.x, c.y, c.z);
        const float whitening = raster::shared::ts_display_whitening(c.x, c.y, c.z);
        // The encoders are this text: the C++ functions every picture goes through.
        const glm::vec3 linear = render::display_linear(x);
        const std::array<std::uint8_t, 3> codes = render::srgb8_pixel(x);
        const float g = gpu[4 * i];
        ASSERT_TRUE(std::isfinite(g)) << "input " << x.x << " " << x.y << " " << x.z;
        worst_gain = std::max(worst_gain, std::abs(double(g) - double(gain)) / double(gain));
        for (int k = 0; k < 3; ++k) {
            ASSERT_EQ(linear[k], raster::shared::ts_display_channel(c[k], gain, whitening)) << x[k];
            const float cpu = raster::srgb_oetf(linear[k]);
            const double value = gpu[4 * i + 1 + std::size_t(k)];
            ASSERT_TRUE(std::isfinite(value)) << "input " << x[k] << " channel " << k;
            worst_value = std::max(worst_value, std::abs(value - double(cpu)));
            const int code_gpu = int(std::lround(255.0 * value));
            EXPECT_LE(std::abs(code_gpu - int(codes[std::size_t(k)])), 1) << x[k];
            codes_off_by_one += code_gpu != int(codes[std::size_t(k)]);
        }
    }
    std::printf("worst |GPU - C++|: gain %.2e relative, display value %.2e; 8-bit codes differing: %d of %zu\n",
                worst_gain, worst_value, codes_off_by_one, 3 * inputs.size());
    EXPECT_LE(worst_gain, kTolerance);
    EXPECT_LE(worst_value, kTolerance);
    EXPECT_LE(codes_off_by_one, int(3 * inputs.size() / 100));
    // A grey pixel is the grey curve; a colour keeps its channels' ratios up to the curve's
    // white, and turns white beyond it continuously (the reddened sun's disc shows white).
    EXPECT_FLOAT_EQ(render::display_linear(glm::vec3(0.18f)).x, render::filmic(0.18f));
    for (float m : {0.9f, 7.0f}) {
        const glm::vec3 warm = render::display_linear(m * glm::vec3(1.0f, 0.45f, 0.08f));
        EXPECT_NEAR(warm.y / warm.x, 0.45, 1e-6) << m;
        EXPECT_NEAR(warm.z / warm.x, 0.08, 1e-6) << m;
    }
    const glm::vec3 below = render::display_linear(TS_FILMIC_WHITE * glm::vec3(1.0f, 0.45f, 0.08f));
    const glm::vec3 above = render::display_linear(1.001f * TS_FILMIC_WHITE * glm::vec3(1.0f, 0.45f, 0.08f));
    EXPECT_NEAR(above.y, below.y, 1e-3);
    EXPECT_GT(above.z, below.z);
    const glm::vec3 sun = render::display_linear(glm::vec3(2e4f, 9e3f, 1.6e3f));
    EXPECT_GT(std::min({sun.x, sun.y, sun.z}), 0.99f);
}

}  // namespace
}  // namespace ts::gpu::display_agreement
