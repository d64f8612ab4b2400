#pragma once
// The pyramid method's march, as the list of samples every receiver and azimuth visits: sample
// k lies tau_k = 2^(k / N) texels away (N = the schedule's samples per octave) and reads the
// level whose texel matches the gap to the next sample (pyramid_shared.h). The CPU
// (pyramid_horizons.cpp) and the GPU (gpu/visibility/gpu_pyramid.cpp) march this same list.
#include <cmath>
#include <vector>

#include "core/visibility/pyramid_shared.hpp"

namespace ts::visibility {

struct PyramidSample {
    double tau;  // distance in texels
    int level;
};

// Samples up to max_tau texels, for a pyramid of `levels` levels.
inline std::vector<PyramidSample> pyramid_samples(int samples_per_octave, int levels, double max_tau) {
    std::vector<PyramidSample> out;
    const double ratio = std::exp2(1.0 / samples_per_octave);
    for (int k = 0;; ++k) {
        const double tau = std::exp2(double(k) / samples_per_octave);
        if (tau > max_tau) break;
        out.push_back({tau, shared::ts_pyramid_sample_level(tau, ratio, levels)});
    }
    return out;
}

// How far a march may go on a width x height grid: twice the diagonal (a march ends at the
// grid's edge anyway; this only bounds the list).
inline double pyramid_max_tau(int width, int height) {
    return 2.0 * std::hypot(double(width), double(height));
}

}  // namespace ts::visibility
