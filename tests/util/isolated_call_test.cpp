// A child process's work comes back as bytes; its failures (an error, a crash, a hang, an
// allocation beyond the allowance) come back as one ts::InputError naming what was read, and
// the caller goes on.
#include "core/util/isolated_call.hpp"

#include <csignal>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/util/error.hpp"

namespace {

using Bytes = std::vector<std::uint8_t>;

std::string error_of(const std::function<Bytes()>& work, const ts::IsolationLimits& limits = {}) {
    try {
        ts::run_isolated(work, "model.obj", limits);
    } catch (const ts::InputError& e) {
        return e.what();
    }
    return "";
}

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

#if !defined(__SANITIZE_ADDRESS__)
TEST(IsolatedCall, AnAllocationBeyondTheAllowanceIsOutOfMemory) {
    ts::IsolationLimits limits;
    limits.extra_address_space_bytes = 64ull << 20;
    const std::string e = error_of(
        []() -> Bytes {
            Bytes huge(std::size_t(1) << 30, 1);
            return Bytes(huge.begin(), huge.begin() + 1);
        },
        limits);
    EXPECT_EQ(e, "model.obj: reading it needs more memory than is available");
}
#endif

}  // namespace
