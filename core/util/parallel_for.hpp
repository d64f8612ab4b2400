#pragma once
// The two ways core/ splits work over a few std::jthreads (the machine has few cores):
//  - parallel_for: items handed out one at a time, for items of very different cost
//    (raymarch rows, sweep azimuths);
//  - parallel_rows: contiguous bands of rows, for rows that all cost about the same (pyramid
//    levels, tiling, hillshade, shading), with small jobs kept on the calling thread.
#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace ts {

// Workers for a request: > 0 as asked, 0 (or less) = one per hardware core (at least 1).
inline int thread_count(int requested) {
    if (requested > 0) return requested;
    const unsigned hw = std::thread::hardware_concurrency();
    return hw == 0 ? 1 : int(hw);
}

// Runs body(item, worker) for item in [0, count) on at most `workers` threads (the caller's
// included); worker < workers, so callers can keep per-worker scratch.
template <class Body>
void parallel_for(int count, int workers, Body&& body) {
    workers = std::clamp(workers, 1, std::max(1, count));
    std::atomic<int> next{0};
    auto run = [&](int worker) {
        for (int i = next.fetch_add(1); i < count; i = next.fetch_add(1)) body(i, worker);
    };
    if (workers == 1) {
        run(0);
        return;
    }
    std::vector<std::jthread> pool;
    pool.reserve(std::size_t(workers - 1));
    for (int w = 1; w < workers; ++w) pool.emplace_back(run, w);
    run(0);
}

// Calls body(row_begin, row_end) on disjoint bands covering [0, rows), in parallel on
// thread_count(threads) threads. Jobs below ~128k units of work (work_per_row * rows) run on
// the calling thread: starting a thread costs more than such a job. The bands (four per thread,
// each of at least ~64k units) are handed out as threads come for them, so a thread that shares
// its core with other work (a frame being written) does fewer of them instead of holding up
// the rest. What a body computes must not depend on where the bands begin.
template <class Body>
void parallel_rows(int rows, int threads, long long work_per_row, Body&& body) {
    constexpr long long kMinWorkPerThread = 64 * 1024;
    int n = std::min(thread_count(threads), std::max(1, rows));
    if (work_per_row * rows < kMinWorkPerThread * 2) n = 1;
    if (n <= 1) {
        body(0, rows);
        return;
    }
    const long long total = std::max(1LL, work_per_row) * rows;
    const int bands = int(std::clamp<long long>(total / kMinWorkPerThread, n, 4LL * n));
    std::atomic<int> next{0};
    auto run = [&] {
        for (int b = next.fetch_add(1); b < bands; b = next.fetch_add(1))
            body(int((long long)rows * b / bands), int((long long)rows * (b + 1) / bands));
    };
    std::vector<std::jthread> workers;
    workers.reserve(std::size_t(n - 1));
    for (int t = 1; t < n; ++t) workers.emplace_back(run);
    run();
}

}  // namespace ts
