// GLSL and C++ evaluate the same core/raster/display_shared.h: the flythrough's shaders and the
// 8-bit encoders of every picture (tone_map.hpp, srgb.hpp) apply one display transform. A
// compute shader evaluates it on the Vulkan device (lavapipe without a GPU), the C++ side
// the same text in float; the validation layer is on and must stay silent.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

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

// Exposed values from far below black to far above white, dense around the sRGB knee
// (0.0031308) and the filmic curve's shoulder, plus the ends and out-of-range inputs.
std::vector<float> make_inputs() {
    std::vector<float> x = {-1.0f, -1e-6f, 0.0f, 0.0031308f, 1.0f, 1e3f, 1e6f};
    for (int i = 0; i <= 4000; ++i) x.push_back(std::pow(10.0f, -6.0f + 9.0f * float(i) / 4000));
    for (int i = 0; i <= 1000; ++i) x.push_back(0.002f + 0.003f * float(i) / 1000);
    return x;
}

TEST_F(DisplayAgreementTest, FilmicAndSrgbAgreeWithTheEncoders) {
    const Context& context = *context_;
    const Kernel kernel(context, "display_agreement.comp", embedded::display_agreement_comp.words,
                        {.storage_buffers = 2, .push_constant_bytes = sizeof(Push)});
    const std::vector<float> inputs = make_inputs();
    const auto count = std::uint32_t(inputs.size());
    const Buffer in = context.create_buffer(inputs.size() * sizeof(float));
    const Buffer out = context.create_buffer(inputs.size() * 3 * sizeof(float));
    std::vector<float> gpu(inputs.size() * 3);
    Batch batch(context);
    batch.upload(in, std::span<const float>(inputs));
    batch.dispatch(kernel, {in, out}, Push{count}, groups_for(count, 64));
    batch.download(out, std::span<float>(gpu));
    batch.submit_and_wait();

    // Both are float, values in [0, 1]: the GLSL pow is bounded loosely by the Vulkan spec
    // (a few ulp), so 1e-6 absolute; the 8-bit code may then differ by one only for a value
    // that lands within that of a rounding boundary.
    constexpr double kTolerance = 1e-6;
    double worst[3] = {0, 0, 0};
    int codes_off_by_one = 0;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const float x = inputs[i];
        const float cpu[3] = {raster::shared::ts_filmic(x), raster::shared::ts_srgb_oetf(x),
                              raster::shared::ts_srgb_oetf(raster::shared::ts_filmic(x))};
        // The encoders are this text: the C++ functions every picture goes through.
        ASSERT_EQ(render::filmic(x), cpu[0]) << x;
        ASSERT_EQ(raster::srgb_oetf(x), cpu[1]) << x;
        for (int k = 0; k < 3; ++k) {
            const double g = gpu[3 * i + k];
            ASSERT_TRUE(std::isfinite(g)) << "input " << x << " output " << k;
            worst[k] = std::max(worst[k], std::abs(g - double(cpu[k])));
        }
        const int code_gpu = int(std::lround(255.0f * gpu[3 * i + 2]));
        const int code_cpu = int(render::srgb8_code(x));
        EXPECT_LE(std::abs(code_gpu - code_cpu), 1) << x;
        codes_off_by_one += code_gpu != code_cpu;
    }
    std::printf("worst |GPU - C++|: filmic %.2e, sRGB OETF %.2e, both %.2e; 8-bit codes differing: %d of %zu\n",
                worst[0], worst[1], worst[2], codes_off_by_one, inputs.size());
    for (double w : worst) EXPECT_LE(w, kTolerance);
    EXPECT_LE(codes_off_by_one, int(inputs.size() / 100));
}

}  // namespace
}  // namespace ts::gpu::display_agreement
