#pragma once
// Every gpu test runs on a Context with the validation layer on and fails on any message the
// layer reports, including those at device and instance destruction.
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "gpu/context.hpp"

namespace ts::gpu::test_support {

class ValidatedTest : public ::testing::Test {
protected:
    ValidatedTest();
    ~ValidatedTest() override;
    void TearDown() override;

    std::shared_ptr<ValidationLog> log_;
    std::unique_ptr<Context> context_;
};

// "" when the log is empty, else its messages one per line (for a failure message).
std::string describe(const ValidationLog& log);

}  // namespace ts::gpu::test_support
