#include "core/render/sequence_exposure.hpp"

#include <algorithm>
#include <cmath>

namespace ts::render {

double ev100_of_scale(double scale) { return std::log2(1000.0 / (1.2 * scale)); }

SequenceExposure::SequenceExposure(double reference_ev, const SequenceExposureOptions& options)
    : reference_ev_(reference_ev), options_(options) {
    options_.half_window = std::max(0, options_.half_window);
}

void SequenceExposure::add(double frame_auto_ev, double time_s) {
    times_.push_back(time_s);
    const double floor_ev = reference_ev_ - options_.max_boost_ev;
    // NaN or infinite: an all-black frame, as dark a target as allowed.
    targets_.push_back(std::isfinite(frame_auto_ev) ? std::max(frame_auto_ev, floor_ev) : floor_ev);
}

void SequenceExposure::finish() { finished_ = true; }

std::size_t SequenceExposure::decided() const {
    if (finished_) return targets_.size();
    const std::size_t k = std::size_t(options_.half_window);
    return targets_.size() > k ? targets_.size() - k : 0;
}

double SequenceExposure::ev(std::size_t k) const {
    const std::size_t half = std::size_t(options_.half_window);
    const std::size_t lo = k > half ? k - half : 0, hi = std::min(targets_.size(), k + half + 1);
    // Truncated at the ends alike, so a series and its reverse get mirrored exposures.
    double sum = 0, weights = 0;
    for (std::size_t j = lo; j < hi; ++j) {
        const double d = options_.tau_s > 0 ? (times_[j] - times_[k]) / options_.tau_s : (j == k ? 0.0 : 1e9);
        const double w = std::exp(-0.5 * d * d);
        sum += w * targets_[j], weights += w;
    }
    return sum / weights;
}

}  // namespace ts::render
