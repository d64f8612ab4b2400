// A child that allocates beyond its address-space allowance is "out of memory", one line. This
// case runs in the release build only: AddressSanitizer reserves terabytes of address space for
// its shadow memory, so no address-space limit can hold under it.
#include <string>

#include <gtest/gtest.h>

#include "tests/util/isolated_error.hpp"

namespace {

using ts::test::Bytes;
using ts::test::error_of;

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

}  // namespace
