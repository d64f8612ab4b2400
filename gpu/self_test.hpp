#pragma once
// A quick end-to-end check of a device: upload, the selftest_saxpy kernel, download, compare.
// `terrashade devices --test` runs it, so a user with a new GPU driver can see it work.
#include <cstdint>
#include <string>

#include "gpu/context.hpp"

namespace ts::gpu {

struct SelfTestResult {
    bool passed = false;
    std::uint32_t values = 0;  // floats computed
    double run_ms = 0.0;       // submit to fence, wall clock
    std::string problem;       // the first wrong value when !passed
};

SelfTestResult run_self_test(const Context& context, std::uint32_t values = 1u << 20);

}  // namespace ts::gpu
