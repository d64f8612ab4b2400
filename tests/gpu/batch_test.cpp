#include <bit>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/batch.hpp"
#include "tests/gpu/validated_context.hpp"

namespace ts::gpu {
namespace {

// Matches the push block of gpu/shaders/selftest_saxpy.comp.
struct SaxpyPush {
    float a;
    std::uint32_t n;
};

const KernelLayout kSaxpyLayout{.storage_buffers = 2, .push_constant_bytes = sizeof(SaxpyPush)};
constexpr std::uint32_t kSaxpyGroupSize = 64;

using BatchTest = test_support::ValidatedTest;

// Small integers: every product and sum is exact in float, so results compare exactly.
std::vector<float> iota_floats(std::size_t n, float start) {
    std::vector<float> values(n);
    std::iota(values.begin(), values.end(), start);
    return values;
}

TEST_F(BatchTest, RunsAKernelOnUploadedDataAndDownloadsTheResult) {
    const Kernel saxpy(*context_, "selftest_saxpy", kSaxpyLayout);
    const std::uint32_t n = 1000;  // not a multiple of the group size: the last group is partial
    const auto xs = iota_floats(n, 0.0f);
    const auto ys = iota_floats(n, 5.0f);
    std::vector<float> result(n, -1.0f);

    Batch batch(*context_);
    const Buffer x = batch.upload_new(std::span<const float>(xs));
    const Buffer y = batch.upload_new(std::span<const float>(ys));
    ASSERT_EQ(y.size(), n * sizeof(float));
    batch.dispatch(saxpy, {x, y}, SaxpyPush{3.0f, n}, groups_for(n, kSaxpyGroupSize));
    batch.download(y, std::span<float>(result));
    batch.submit_and_wait();

    for (std::uint32_t i = 0; i < n; ++i) ASSERT_EQ(result[i], 3.0f * xs[i] + ys[i]) << "at " << i;
}

TEST_F(BatchTest, OrdersDependentDispatchesAndCanBeReused) {
    const Kernel saxpy(*context_, "selftest_saxpy.comp", kSaxpyLayout);
    const std::uint32_t n = 300;
    const auto xs = iota_floats(n, 1.0f);
    const std::vector<float> zeros(n, 0.0f);
    const Buffer x = context_->create_buffer(n * sizeof(float));
    const Buffer y = context_->create_buffer(n * sizeof(float), MemoryKind::host_visible);
    std::vector<float> result(n);

    Batch batch(*context_);
    for (int round = 0; round < 2; ++round) {
        batch.upload(x, std::span<const float>(xs));
        batch.upload(y, std::span<const float>(zeros));
        // y = x, then y = 2x + y = 3x, then y = -1x + y = 2x: only right if each waits for the last.
        batch.dispatch(saxpy, {x, y}, SaxpyPush{1.0f, n}, groups_for(n, kSaxpyGroupSize));
        batch.dispatch(saxpy, {x, y}, SaxpyPush{2.0f, n}, groups_for(n, kSaxpyGroupSize));
        batch.dispatch(saxpy, {x, y}, SaxpyPush{-1.0f, n}, groups_for(n, kSaxpyGroupSize));
        batch.download(y, std::span<float>(result));
        batch.submit_and_wait();
        for (std::uint32_t i = 0; i < n; ++i) ASSERT_EQ(result[i], 2.0f * xs[i]) << "round " << round << " at " << i;
    }
}

TEST_F(BatchTest, ManyDispatchesOutgrowOneDescriptorPool) {
    const Kernel saxpy(*context_, "selftest_saxpy", kSaxpyLayout);
    const std::uint32_t n = 64;
    const auto ones = std::vector<float>(n, 1.0f);
    const Buffer x = context_->create_buffer(n * sizeof(float));
    const Buffer y = context_->create_buffer(n * sizeof(float));
    std::vector<float> result(n);
    const int dispatches = 200;  // more sets than one pool holds (64)

    Batch batch(*context_);
    batch.upload(x, std::span<const float>(ones));
    batch.upload(y, std::span<const float>(std::vector<float>(n, 0.0f)));
    for (int i = 0; i < dispatches; ++i) batch.dispatch(saxpy, {x, y}, SaxpyPush{1.0f, n}, groups_for(n, 64));
    batch.download(y, std::span<float>(result));
    batch.submit_and_wait();
    for (float value : result) ASSERT_EQ(value, static_cast<float>(dispatches));
}

TEST_F(BatchTest, PartialUploadAndDownloadUseOffsets) {
    const std::vector<std::uint32_t> values = {1, 2, 3, 4};
    const Buffer buffer = context_->create_buffer(8 * sizeof(std::uint32_t));
    std::vector<std::uint32_t> middle(4);

    Batch batch(*context_);
    batch.upload(buffer, std::span<const std::uint32_t>(values), 2 * sizeof(std::uint32_t));
    batch.download(buffer, std::span<std::uint32_t>(middle), 2 * sizeof(std::uint32_t));
    batch.submit_and_wait();
    EXPECT_EQ(middle, values);
}

TEST_F(BatchTest, RejectsMismatchedBindingsPushConstantsAndRanges) {
    const Kernel saxpy(*context_, "selftest_saxpy", kSaxpyLayout);
    const Buffer x = context_->create_buffer(16);
    Batch batch(*context_);
    EXPECT_THROW(batch.dispatch(saxpy, {x}, SaxpyPush{1.0f, 4}, Groups{}), std::invalid_argument);
    EXPECT_THROW(batch.dispatch(saxpy, {x, x}, 1.0f, Groups{}), std::invalid_argument);
    EXPECT_THROW(batch.dispatch(saxpy, {x, x}, SaxpyPush{1.0f, 4}, Groups{UINT32_MAX, 1, 1}), std::invalid_argument);
    const std::vector<float> too_many(5, 0.0f);
    EXPECT_THROW(batch.upload(x, std::span<const float>(too_many)), std::out_of_range);
    std::vector<float> too_few_bytes_left(2);
    EXPECT_THROW(batch.download(x, std::span<float>(too_few_bytes_left), 12), std::out_of_range);
}

TEST_F(BatchTest, CopiesAndFillsOnTheDevice) {
    const std::vector<float> values = {1.5f, -2.0f, 3.25f, 8.0f};
    const Buffer a = context_->create_buffer(values.size() * sizeof(float));
    const Buffer b = context_->create_buffer(values.size() * sizeof(float));
    const Buffer c = context_->create_buffer(values.size() * sizeof(float));
    std::vector<float> copied(values.size()), filled(values.size()), tail(2);

    Batch batch(*context_);
    batch.upload(a, std::span<const float>(values));
    batch.copy(a, b);
    batch.fill(c, std::bit_cast<std::uint32_t>(0.5f));
    batch.copy(a, c, 2 * sizeof(float), 2 * sizeof(float), 0);  // the last two values to the front
    batch.download(b, std::span<float>(copied));
    batch.download(c, std::span<float>(filled));
    batch.fill(a);  // after the copies: b and c keep what a held before
    batch.download(a, std::span<float>(tail), 2 * sizeof(float));
    batch.submit_and_wait();

    EXPECT_EQ(copied, values);
    EXPECT_EQ(filled, (std::vector<float>{3.25f, 8.0f, 0.5f, 0.5f}));
    EXPECT_EQ(tail, (std::vector<float>{0.0f, 0.0f}));
}

TEST_F(BatchTest, TimesStagesBetweenMarks) {
    const Kernel saxpy(*context_, "selftest_saxpy", kSaxpyLayout);
    const std::uint32_t n = 1 << 16;
    const Buffer x = context_->create_buffer(n * sizeof(float));
    const Buffer y = context_->create_buffer(n * sizeof(float));
    Batch batch(*context_);
    batch.fill(x);
    batch.fill(y);
    batch.mark("clear");
    for (int i = 0; i < 4; ++i) batch.dispatch(saxpy, {x, y}, SaxpyPush{1.0f, n}, groups_for(n, kSaxpyGroupSize));
    batch.mark("saxpy");
    batch.submit_and_wait();
    ASSERT_EQ(batch.stage_times().size(), 2u);
    EXPECT_EQ(batch.stage_times()[0].label, "clear");
    EXPECT_EQ(batch.stage_times()[1].label, "saxpy");
    if (context_->device_info().timestamp_valid_bits > 0) {
        // No timing assertion beyond sanity: a finite, non-negative duration.
        for (const auto& stage : batch.stage_times()) {
            EXPECT_TRUE(std::isfinite(stage.ms)) << stage.label;
            EXPECT_GE(stage.ms, 0.0) << stage.label;
            std::printf("stage %s: %.3f ms (whole run %.3f ms)\n", stage.label.c_str(), stage.ms, batch.last_run_ms());
        }
    }
    batch.submit_and_wait();  // nothing recorded: the times of the last run stay
    EXPECT_EQ(batch.stage_times().size(), 2u);
}

TEST_F(BatchTest, ReportsDeviceLocalMemory) { EXPECT_GT(context_->device_local_bytes(), 0u); }

TEST(Groups, CoverAllItemsRoundingUp) {
    EXPECT_EQ(groups_for(1000, 64).x, 16u);
    EXPECT_EQ(groups_for(1024, 64).x, 16u);
    EXPECT_EQ(groups_for(0, 64).x, 0u);
    const Groups image = groups_for(1201, 1201, 16, 8);
    EXPECT_EQ(image.x, 76u);
    EXPECT_EQ(image.y, 151u);
    EXPECT_EQ(image.z, 1u);
}

}  // namespace
}  // namespace ts::gpu
