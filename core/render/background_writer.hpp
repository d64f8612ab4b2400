#pragma once
// Writes frames (render::write_image: tone mapping, PNG/TIFF/EXR encoding, atomic temp + rename)
// on a thread of its own while the caller renders the next frame. A sequence of frames is
// encoder-bound (a 500x500 PNG takes longer to tone-map and compress than to relight), so
// overlapping the two hides most of the rendering.
//
//   BackgroundWriter writer(2);
//   for (...) { scene.render(sun, image); writer.write(path, image, exposure, georef); }
//   writer.finish();   // waits; rethrows the first write error
//
// At most `queue_frames` frames wait (memory stays bounded whatever the encoder's speed); the
// caller blocks when the queue is full. An error is reported by the next write() or finish(),
// and no further frame is written after it.
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/geo/georef.hpp"
#include "core/render/render_scene.hpp"
#include "core/render/tone_map.hpp"

namespace ts::render {

class BackgroundWriter {
public:
    explicit BackgroundWriter(int queue_frames = 2);
    // Waits for the queued frames (errors are dropped: call finish() to see them).
    ~BackgroundWriter();
    BackgroundWriter(const BackgroundWriter&) = delete;
    BackgroundWriter& operator=(const BackgroundWriter&) = delete;

    // Queues `image` for write_image(path, image, exposure, georef) and hands back in `image` the
    // storage of an earlier frame (contents unspecified, same size once the queue has cycled), so
    // the caller renders the next frame without allocating. `georef` must stay valid until
    // finish(). Throws the error of an earlier write, if any.
    void write(std::string path, LinearImage& image, const Exposure& exposure, const geo::Georef* georef);
    // Waits until every queued frame is written; throws the first write error.
    void finish();

private:
    struct Job {
        std::string path;
        LinearImage image;
        Exposure exposure;
        const geo::Georef* georef = nullptr;
    };
    void run();
    void rethrow_error_locked();

    const std::size_t capacity_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<Job> queue_;
    std::vector<LinearImage> spare_;  // written frames' storage, reused by write()
    bool busy_ = false;               // the thread is writing a frame taken off the queue
    bool stop_ = false;
    std::exception_ptr error_;
    std::jthread thread_;             // last: started after the members it uses exist
};

}  // namespace ts::render
