#pragma once
// Exposure for a time-lapse: each frame's automatic exposure, smoothed from frame to frame and
// bounded against the brightest frame, so that dawn and dusk are readable, noon is not washed
// out, night stays night, and nothing flickers.
//
// In EV100 (lower EV = brighter picture): the frame's own auto EV is first held to at most
// `max_boost_ev` below the reference EV (the auto EV of the frame with the highest sun), so a
// twilight frame is brightened by at most that many stops and a night frame stays dark instead
// of amplifying a near-black sky to middle grey; then an exponential moving average over frames,
//   ev_k = ev_{k-1} + smoothing * (target_k - ev_{k-1}),   ev_0 = target_0,
// takes out frame-to-frame jumps (moving shadows change the log-average a little each frame).
#include "core/render/tone_map.hpp"

namespace ts::render {

struct SequenceExposureOptions {
    double max_boost_ev = 3.0;  // at most 8x the brightest frame's exposure
    double smoothing = 0.5;     // 1 = every frame its own exposure, towards 0 = one exposure
};

// EV100 <-> the linear scale of core/render/tone_map.hpp: scale = 1000 / (1.2 * 2^EV).
double ev100_of_scale(double scale);

class SequenceExposure {
public:
    // `reference_ev`: the auto EV100 of the brightest frame (the highest sun).
    SequenceExposure(double reference_ev, const SequenceExposureOptions& options = {});
    // The EV100 for the next frame, from that frame's own automatic EV100.
    double next(double frame_auto_ev);

private:
    double reference_ev_;
    SequenceExposureOptions options_;
    bool started_ = false;
    double ev_ = 0;
};

}  // namespace ts::render
