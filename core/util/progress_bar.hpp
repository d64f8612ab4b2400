#pragma once
// A progress bar with rate and ETA on a terminal; silent when stderr is not a terminal
// (piped, CI) or when disabled, so logs stay clean.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace ts {

class ProgressBar {
public:
    // `label` names the work, `total` counts its units (texels, tiles, frames), `unit` names one.
    ProgressBar(std::string label, std::uint64_t total, std::string unit = "it");
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    // Thread-safe; redraws at most ~10 times a second.
    void advance(std::uint64_t n = 1);
    void finish();

    std::uint64_t done() const { return done_.load(std::memory_order_relaxed); }
    bool enabled() const { return enabled_; }
    // Force on/off (tests; --quiet). Default: on iff stderr is a terminal.
    void set_enabled(bool on) { enabled_ = on; }

private:
    void draw(bool final_line);

    std::string label_;
    std::string unit_;
    std::uint64_t total_;
    std::atomic<std::uint64_t> done_{0};
    bool enabled_;
    bool finished_ = false;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point last_draw_;
    std::mutex mutex_;
};

}  // namespace ts
