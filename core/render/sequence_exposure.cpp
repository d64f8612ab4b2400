#include "core/render/sequence_exposure.hpp"

#include <algorithm>
#include <cmath>

namespace ts::render {

double ev100_of_scale(double scale) { return std::log2(1000.0 / (1.2 * scale)); }

SequenceExposure::SequenceExposure(double reference_ev, const SequenceExposureOptions& options)
    : reference_ev_(reference_ev), options_(options) {}

double SequenceExposure::next(double frame_auto_ev) {
    const double target = std::isfinite(frame_auto_ev)
                              ? std::max(frame_auto_ev, reference_ev_ - options_.max_boost_ev)
                              : reference_ev_ - options_.max_boost_ev;  // an all-black frame
    ev_ = started_ ? ev_ + options_.smoothing * (target - ev_) : target;
    started_ = true;
    return ev_;
}

}  // namespace ts::render
