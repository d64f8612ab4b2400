// Specialization constants reach the shader: a value and the workgroup size, both fixed when
// the pipeline is made.
#include <vector>

#include <gtest/gtest.h>

#include "gpu/batch.hpp"
#include "gpu/spirv.hpp"
#include "tests/gpu/validated_context.hpp"

namespace ts::gpu::embedded {
extern const SpirvBlob specialized_fill_comp;  // tests/gpu/shaders/specialized_fill.comp
}

namespace ts::gpu {
namespace {

using SpecializationTest = test_support::ValidatedTest;

TEST_F(SpecializationTest, SetsAConstantAndTheWorkgroupSize) {
    const std::uint32_t value = 42, group_size = 32, n = 100;
    const Kernel fill(*context_, "specialized_fill", embedded::specialized_fill_comp.words,
                      {.storage_buffers = 1, .push_constant_bytes = 4, .specialization = {value, group_size}});
    const Buffer out = context_->create_buffer(n * sizeof(std::uint32_t));
    std::vector<std::uint32_t> result(n);
    Batch batch(*context_);
    batch.dispatch(fill, {out}, n, groups_for(n, group_size));
    batch.download(out, std::span<std::uint32_t>(result));
    batch.submit_and_wait();
    // The shader adds 1000000 if the workgroup size is not 32.
    EXPECT_EQ(result, std::vector<std::uint32_t>(n, value));
}

}  // namespace
}  // namespace ts::gpu
