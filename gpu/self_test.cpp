#include "gpu/self_test.hpp"

#include <vector>

#include "gpu/batch.hpp"

namespace ts::gpu {
namespace {

struct SaxpyPush {
    float a;
    std::uint32_t n;
};

}  // namespace

SelfTestResult run_self_test(const Context& context, std::uint32_t values) {
    const Kernel saxpy(context, "selftest_saxpy", {.storage_buffers = 2, .push_constant_bytes = sizeof(SaxpyPush)});
    // Values below 2^12 keep 3x + y exact in float, so the comparison can be exact.
    std::vector<float> xs(values), ys(values), result(values);
    for (std::uint32_t i = 0; i < values; ++i) {
        xs[i] = static_cast<float>(i % 4096);
        ys[i] = static_cast<float>((i * 7u) % 4096);
    }
    const Buffer x = context.create_buffer(std::uint64_t{values} * sizeof(float));
    const Buffer y = context.create_buffer(std::uint64_t{values} * sizeof(float));
    Batch batch(context);
    batch.upload(x, std::span<const float>(xs));
    batch.upload(y, std::span<const float>(ys));
    batch.dispatch(saxpy, {x, y}, SaxpyPush{3.0f, values}, groups_for(values, 64));
    batch.download(y, std::span<float>(result));
    batch.submit_and_wait();

    SelfTestResult outcome;
    outcome.values = values;
    outcome.run_ms = batch.last_run_ms();
    for (std::uint32_t i = 0; i < values; ++i) {
        const float expected = 3.0f * xs[i] + ys[i];
        if (result[i] != expected) {
            outcome.problem = "value " + std::to_string(i) + " is " + std::to_string(result[i]) + ", expected " +
                              std::to_string(expected);
            return outcome;
        }
    }
    outcome.passed = true;
    return outcome;
}

}  // namespace ts::gpu
