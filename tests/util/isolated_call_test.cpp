// A child process's work comes back as bytes; its failures (an error, a crash, a hang; an
// allocation beyond the allowance in isolated_call_memory_test.cpp) come back as one
// ts::InputError naming what was read, and the caller goes on.
#include "core/util/isolated_call.hpp"

#include <csignal>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/util/isolated_error.hpp"

namespace {

using ts::test::Bytes;
using ts::test::error_of;

TEST(IsolatedCall, ReturnsTheChildsBytesLargerThanAPipeBuffer) {
    Bytes big(3'000'000);
    for (std::size_t i = 0; i < big.size(); ++i) big[i] = std::uint8_t(i * 7 + 3);
    EXPECT_EQ(ts::run_isolated([&] { return big; }, "x"), big);
    EXPECT_TRUE(ts::run_isolated([] { return Bytes{}; }, "x").empty());
}

TEST(IsolatedCall, AnErrorInTheChildKeepsItsMessage) {
    EXPECT_EQ(error_of([]() -> Bytes { throw ts::InputError("model.obj: no triangles"); }), "model.obj: no triangles");
}

TEST(IsolatedCall, AChildKilledByASignalIsAnErrorNotACrash) {
    const std::string e = error_of([]() -> Bytes {
        std::raise(SIGKILL);
        return {};
    });
    EXPECT_EQ(e.rfind("model.obj: the reader crashed on it", 0), 0u) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos);
}

TEST(IsolatedCall, AHungChildIsKilledAtTheTimeout) {
    ts::IsolationLimits limits;
    limits.timeout_s = 0.3;
    const std::string e = error_of(
        []() -> Bytes {
            std::this_thread::sleep_for(std::chrono::seconds(30));
            return {};
        },
        limits);
    EXPECT_EQ(e.rfind("model.obj: reading it did not finish", 0), 0u) << e;
}

}  // namespace
