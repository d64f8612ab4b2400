#include "core/render/background_writer.hpp"

#include <algorithm>
#include <utility>

namespace ts::render {

BackgroundWriter::BackgroundWriter(int queue_frames, int threads) : capacity_(std::size_t(std::max(1, queue_frames))) {
    const int n = std::max(1, threads);
    threads_.reserve(std::size_t(n));
    try {
        for (int i = 0; i < n; ++i) threads_.emplace_back([this] { run(); });
    } catch (...) {
        // The threads already started must see stop_ to return before they are joined.
        {
            std::lock_guard lock(mutex_);
            stop_ = true;
        }
        changed_.notify_all();
        throw;
    }
}

BackgroundWriter::~BackgroundWriter() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    changed_.notify_all();
    // The jthreads join; run() drains the queue first (or drops it after an error).
}

void BackgroundWriter::rethrow_error_locked() {
    if (error_) std::rethrow_exception(error_);
}

void BackgroundWriter::write(std::string path, LinearImage& image, const Exposure& exposure,
                             const geo::Georef* georef) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return error_ || queue_.size() < capacity_; });
    rethrow_error_locked();
    Job job{std::move(path), std::move(image), exposure, georef};
    if (!spare_.empty()) {
        image = std::move(spare_.back());
        spare_.pop_back();
    } else {
        image = LinearImage{};
    }
    queue_.push_back(std::move(job));
    lock.unlock();
    changed_.notify_all();
}

void BackgroundWriter::finish() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return error_ ? busy_ == 0 : queue_.empty() && busy_ == 0; });
    rethrow_error_locked();
}

void BackgroundWriter::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        changed_.wait(lock, [&] { return stop_ || !queue_.empty(); });
        if (queue_.empty() || error_) {
            if (stop_) return;
            queue_.clear();  // after an error nothing more is written
            continue;
        }
        Job job = std::move(queue_.front());
        queue_.pop_front();
        ++busy_;
        lock.unlock();
        changed_.notify_all();  // a slot is free: the caller may queue the next frame now
        std::exception_ptr failed;
        try {
            write_image(job.path, job.image, job.exposure, job.georef);
        } catch (...) {
            failed = std::current_exception();
        }
        lock.lock();
        --busy_;
        if (failed && !error_) error_ = failed;
        spare_.push_back(std::move(job.image));
        changed_.notify_all();
    }
}

}  // namespace ts::render
