#pragma once
// Exposure for a time-lapse: each frame's automatic exposure, bounded against the brightest
// frame and smoothed over its neighbours, so that dawn and dusk are readable, noon is not washed
// out, night stays night, nothing flickers, and a morning and an evening at the same sun get the
// same exposure.
//
// In EV100 (lower EV = brighter picture): the frame's own auto EV is first held to at most
// `max_boost_ev` below the reference EV (the auto EV of the frame with the highest sun), so a
// twilight frame is brightened by at most that many stops and a night frame stays dark instead
// of amplifying a near-black sky to middle grey; then each frame takes a weighted mean of these
// targets over the frames k-K..k+K that exist (K = half_window), the weights falling with the
// time between the frames,
//   ev_k = sum_j w_kj target_j / sum_j w_kj,   w_kj = exp(-((t_j - t_k) / tau)^2 / 2),
// a centred (zero-phase) average: it takes out frame-to-frame jumps of a dense series (moving
// shadows change the log-average a little each frame) without the lag of a running average,
// which made mornings brighter than evenings (0.6 EV at equal sun elevations with the
// exponential average of earlier versions); and frames far apart in time (hourly) keep their
// own exposure instead of taking noon's into dawn. Frame k's EV is known once frame k+K has
// been added: the caller holds K frames back.
#include <cstddef>
#include <vector>

#include "core/render/tone_map.hpp"

namespace ts::render {

struct SequenceExposureOptions {
    // At most 1024x the brightest frame's exposure: the physical sky's dawn (6.4 EV under noon
    // with the sun 1 degree up) at its own exposure, its twilight (12.6 EV under at -5) a dark
    // blue, the night black (docs/user-guide.md, relight). 8 left that twilight at mean code 5.
    double max_boost_ev = 10.0;
    int half_window = 2;        // K: frames on each side averaged (0 = every frame its own)
    double tau_s = 900.0;       // the weights' time scale: 15 minutes
};

// EV100 <-> the linear scale of core/render/tone_map.hpp: scale = 1000 / (1.2 * 2^EV).
double ev100_of_scale(double scale);

class SequenceExposure {
public:
    // `reference_ev`: the auto EV100 of the brightest frame (the highest sun).
    explicit SequenceExposure(double reference_ev, const SequenceExposureOptions& options = {});
    // The next frame's own automatic EV100, and its time in seconds (increasing).
    void add(double frame_auto_ev, double time_s);
    // No frame follows: every frame added is decided.
    void finish();
    // How many frames, from the first, have their EV decided.
    std::size_t decided() const;
    // Frame k's EV100; k < decided().
    double ev(std::size_t k) const;
    int lookahead() const { return options_.half_window; }

private:
    double reference_ev_;
    SequenceExposureOptions options_;
    std::vector<double> targets_, times_;
    bool finished_ = false;
};

}  // namespace ts::render
