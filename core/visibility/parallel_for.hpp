#pragma once
// Runs body(i, worker) for i in [0, count) on a few std::jthreads, handing out items one at a
// time (raymarch rows and sweep azimuths cost very different amounts, so the split is dynamic).
#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace ts::visibility {

inline int thread_count(int requested) {
    if (requested > 0) return requested;
    const unsigned hw = std::thread::hardware_concurrency();
    return hw == 0 ? 1 : int(hw);
}

// body(item, worker_index); worker_index < workers so callers can keep per-worker scratch.
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
    for (int w = 1; w < workers; ++w) pool.emplace_back(run, w);
    run(0);
}

}  // namespace ts::visibility
