#pragma once
// Writes frames (render::write_image: tone mapping, PNG/TIFF/EXR encoding, atomic temp + rename)
// on threads of their own while the caller renders the next frame. A sequence of frames can be
// encoder-bound (tone mapping and compressing a 500x500 PNG takes about as long as relighting
// it), so overlapping the two hides most of the encoding, and with several writer threads
// several frames are encoded at once.
//
//   BackgroundWriter writer(2, 2);
//   for (...) { scene.render(sun, image); writer.write(path, image, exposure, georef); }
//   writer.finish();   // waits; rethrows the first write error
//
// At most `queue_frames` frames wait (memory stays bounded whatever the encoder's speed: the
// caller blocks when the queue is full), besides the one each writer thread is writing. Every
// frame is renamed into place as soon as its own write is done, so with several threads the
// files may appear out of order. An error is reported by the next write() or finish(); once
// it happened no further queued frame is started (frames already being written still finish,
// each completely or not at all: write_image never leaves a temporary file).
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

// Writer threads `relight` and `bench relight` start unless told otherwise. Writing a 500x500
// frame (tone map + PNG) costs about as much CPU as relighting it, so on 2 cores one writer
// thread competing with two shading threads can fall behind; two did better in interleaved
// runs of `bench relight --cpu` (median 13.9 against 12.6 Mpx/s end to end), three no better
// than two (docs/performance.md, "PNG output").
inline constexpr int kDefaultWriterThreads = 2;

class BackgroundWriter {
public:
    explicit BackgroundWriter(int queue_frames = 2, int threads = 1);
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
    int busy_ = 0;                    // threads writing a frame taken off the queue
    bool stop_ = false;
    std::exception_ptr error_;
    std::vector<std::jthread> threads_;  // last: started after the members they use exist
};

}  // namespace ts::render
