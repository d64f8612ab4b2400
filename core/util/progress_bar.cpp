#include "core/util/progress_bar.hpp"

#include <cstdio>
#include <unistd.h>

namespace ts {

ProgressBar::ProgressBar(std::string label, std::uint64_t total, std::string unit)
    : label_(std::move(label)), unit_(std::move(unit)), total_(total),
      enabled_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::advance(std::uint64_t n) {
    done_.fetch_add(n, std::memory_order_relaxed);
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock() || now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    draw(false);
}

void ProgressBar::finish() {
    if (finished_) return;
    finished_ = true;
    if (!enabled_) return;
    std::lock_guard lock(mutex_);
    draw(true);
}

void ProgressBar::draw(bool final_line) {
    const std::uint64_t done = std::min(done_.load(std::memory_order_relaxed), total_);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double frac = total_ ? double(done) / double(total_) : 1.0;
    const double rate = secs > 0 ? double(done) / secs : 0.0;
    const double eta = rate > 0 ? double(total_ - done) / rate : 0.0;
    constexpr int width = 30;
    const int filled = int(frac * width + 0.5);
    char bar[width + 1];
    for (int i = 0; i < width; ++i) bar[i] = i < filled ? '#' : '-';
    bar[width] = '\0';
    const char* scale = "";
    double shown = rate;
    if (rate >= 1e6) { shown = rate / 1e6; scale = "M"; }
    else if (rate >= 1e3) { shown = rate / 1e3; scale = "k"; }
    std::fprintf(stderr, "\r%s [%s] %3.0f%% %.1f %s%s/s ETA %.0fs   ", label_.c_str(), bar,
                 frac * 100.0, shown, scale, unit_.c_str(), eta);
    if (final_line) std::fprintf(stderr, "\n");
    std::fflush(stderr);
}

}  // namespace ts
