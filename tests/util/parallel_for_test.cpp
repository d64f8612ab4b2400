// parallel_for / parallel_rows: every item (row) is handled exactly once, on a valid worker.
#include "core/util/parallel_for.hpp"

#include <atomic>
#include <vector>

#include <gtest/gtest.h>

namespace ts {
namespace {

TEST(ParallelFor, EveryItemOnceOnAValidWorker) {
    for (const int workers : {1, 2, 3, 8}) {
        const int count = 1001;
        std::vector<std::atomic<int>> hits(count);
        std::atomic<int> bad_worker{0};
        parallel_for(count, workers, [&](int i, int worker) {
            hits[std::size_t(i)].fetch_add(1);
            if (worker < 0 || worker >= workers) bad_worker.fetch_add(1);
        });
        for (int i = 0; i < count; ++i) ASSERT_EQ(hits[std::size_t(i)].load(), 1) << i << " workers " << workers;
        EXPECT_EQ(bad_worker.load(), 0);
    }
    int calls = 0;
    parallel_for(0, 4, [&](int, int) { ++calls; });
    EXPECT_EQ(calls, 0);
}

TEST(ParallelFor, RowsAreCoveredByDisjointBands) {
    // Enough work per row that the job really is split over threads.
    for (const int threads : {1, 2, 3, 7}) {
        const int rows = 997;
        std::vector<std::atomic<int>> hits(rows);
        parallel_rows(rows, threads, 1 << 20, [&](int begin, int end) {
            for (int r = begin; r < end; ++r) hits[std::size_t(r)].fetch_add(1);
        });
        for (int r = 0; r < rows; ++r) ASSERT_EQ(hits[std::size_t(r)].load(), 1) << r << " threads " << threads;
    }
}

TEST(ParallelFor, ThreadCountKeepsRequestsAndResolvesZero) {
    EXPECT_EQ(thread_count(3), 3);
    EXPECT_GE(thread_count(0), 1);
}

}  // namespace
}  // namespace ts
