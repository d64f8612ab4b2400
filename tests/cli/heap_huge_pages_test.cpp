// main()'s re-exec with glibc's malloc on transparent huge pages (app/heap_huge_pages.hpp): the
// tunable is added to the user's others, never twice (a process that has it does not re-execute
// again), and the user's own setting of it is kept; every command still runs once with it unset,
// set by the user, or the re-exec turned off.
#include <gtest/gtest.h>

#include "app/heap_huge_pages.hpp"
#include "cli_support.hpp"

namespace ts::cli_test {
namespace {

TEST(HeapHugePages, TheTunableIsAddedOnceAndTheUsersOwnKept) {
    EXPECT_EQ(app::tunables_with_huge_pages(nullptr), "glibc.malloc.hugetlb=1");
    EXPECT_EQ(app::tunables_with_huge_pages(""), "glibc.malloc.hugetlb=1");
    EXPECT_EQ(app::tunables_with_huge_pages("glibc.malloc.arena_max=2"),
              "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1");
    EXPECT_EQ(app::tunables_with_huge_pages("glibc.malloc.hugetlb=1"), std::nullopt);
    EXPECT_EQ(app::tunables_with_huge_pages("glibc.malloc.arena_max=2:glibc.malloc.hugetlb=0"), std::nullopt);
}

TEST(HeapHugePages, CommandsRunWithTheTunableUnsetSetOrTurnedOff) {
    for (const char* env : {"env -u GLIBC_TUNABLES ", "GLIBC_TUNABLES=glibc.malloc.hugetlb=0 ",
                            "TERRASHADE_NO_HUGE_PAGES=1 "}) {
        const Result r = run_ts("info " + quote(kSharedDems + "copernicus_N45E005_grenoble_500px.tif"), env);
        EXPECT_EQ(r.exit_code, 0) << env << r.err;
        EXPECT_NE(r.out.find("500"), std::string::npos) << env << r.out;
    }
}

}  // namespace
}  // namespace ts::cli_test
