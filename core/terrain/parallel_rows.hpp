#pragma once
// Splits a range of rows over a few std::jthreads. The machine has few cores, so the split is
// static (equal contiguous bands): every caller's rows cost the same.
#include <algorithm>
#include <thread>
#include <vector>

namespace ts::terrain {

// 0 = one thread per hardware core (at least 1).
inline int resolve_thread_count(int requested) {
    if (requested > 0) return requested;
    const unsigned hw = std::thread::hardware_concurrency();
    return hw == 0 ? 1 : int(hw);
}

// Calls body(row_begin, row_end) on disjoint bands covering [0, rows), in parallel.
// Small jobs run on the calling thread: a thread start costs ~50 us.
template <class Body>
void parallel_rows(int rows, int threads, long long work_per_row, Body&& body) {
    constexpr long long kMinWorkPerThread = 64 * 1024;
    int n = std::min(resolve_thread_count(threads), std::max(1, rows));
    if (work_per_row * rows < kMinWorkPerThread * 2) n = 1;
    if (n <= 1) {
        body(0, rows);
        return;
    }
    std::vector<std::jthread> workers;
    workers.reserve(std::size_t(n - 1));
    for (int t = 1; t < n; ++t) {
        const int begin = int((long long)rows * t / n);
        const int end = int((long long)rows * (t + 1) / n);
        workers.emplace_back([&body, begin, end] { body(begin, end); });
    }
    body(0, int((long long)rows / n));
}

}  // namespace ts::terrain
